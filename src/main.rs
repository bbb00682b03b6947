//! The `ugo` command line (`docs/design.md` §6): `solve`, `norms`, `compare`, `render`, `trace`,
//! `agree`, `info`, `bench`, `export`, `probes`, `glare`.

/// `println!` that outlives its reader: once whoever reads standard output has gone (`ugo
/// solve … | head -1`), the lines are dropped and the command goes on to write its files,
/// where `println!` would panic.
macro_rules! say {
    ($($line:tt)*) => {{
        use std::io::Write as _;
        let _ = writeln!(std::io::stdout(), $($line)*);
    }};
}

mod cli;

use clap::{Parser, Subcommand};
use cli::options::{Discretize, ScaleArg, ShadingArg, Stopping, method};
use cli::solve::Job;
use std::path::PathBuf;
use std::process::ExitCode;
use ugo::solve::{Method, RESTART, SolveParams};
use ugo::study;

/// A numerical laboratory for the global illumination equation of a 3D scene.
#[derive(Parser)]
#[command(name = "ugo", version, about)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Mesh, assemble and solve a case; write the luminance field to HDF5.
    Solve {
        /// The case file (TOML).
        case: PathBuf,
        /// Output HDF5 file (default: the case's name with `.h5`, in the current folder).
        #[arg(short, long)]
        output: Option<PathBuf>,
        #[command(flatten)]
        discretize: Discretize,
        #[command(flatten)]
        stopping: Stopping,
        /// Method: neumann, gauss-seidel, southwell, gmres[:M], bicgstab, direct (default: the case's).
        #[arg(long, value_parser = method)]
        method: Option<Method>,
        /// Reflection orders whose partial sums go to /orders (default 1,8,64 with neumann).
        #[arg(long, allow_negative_numbers = true, value_delimiter = ',', value_parser = cli::options::order)]
        orders: Option<Vec<usize>>,
        /// Also compute the norms of K (from the explicit product; matrix-free, without
        /// ‖K‖_F and ‖K‖₂, when it is over the memory limit).
        #[arg(long)]
        norms: bool,
        #[command(flatten)]
        basis: cli::basis::BasisOptions,
        #[command(flatten)]
        kernel: cli::kernel::KernelOptions,
        /// Link only the hierarchy's receivers of part I of N (I from 0) and write them to
        /// their own file (default `<case>-part-I-of-N.h5`), without solving: the initial
        /// linking only (docs/petsc.md, "Parts").
        #[arg(long, value_name = "I/N")]
        part: Option<ugo::kernel::hierarchy::Part>,
        /// With --part: the part files of every part (`solve --part` of each); instead of
        /// linking, rebuild the tree from them and write part I's rows of the operator and
        /// of the source term (default `<case>-rows-I-of-N.h5`) for `tools/petsc/run
        /// --from-parts` (docs/petsc.md, "The operator from the part files").
        #[arg(long, num_args = 1.., value_name = "PART_FILE", requires = "part")]
        linked: Vec<PathBuf>,
    },
    /// Join part files (`solve --part I/N`): refused unless every part of one partition of
    /// one case; prints each part's links, bytes and cut links.
    Parts {
        /// The part files, one per part.
        #[arg(required = true)]
        files: Vec<PathBuf>,
    },
    /// Norms of K, its spectral radius, cond(I − K) and the predicted Neumann iterations.
    Norms {
        case: PathBuf,
        /// Output HDF5 file (default: `<case>-norms.h5`).
        #[arg(short, long)]
        output: Option<PathBuf>,
        #[command(flatten)]
        discretize: Discretize,
        #[command(flatten)]
        stopping: Stopping,
        #[command(flatten)]
        kernel: cli::kernel::KernelOptions,
        /// Also the N eigenvalues of K of largest magnitude and their eigenvectors (ugo's
        /// Arnoldi, matrix-free), to /spectrum; runs GMRES beside successive approximation
        /// and plots both against the rates the spectrum predicts (`<output>-spectrum.png`).
        #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..=1000))]
        spectrum: Option<u32>,
    },
    /// Solve with several methods side by side: table, convergence plot, histories in HDF5.
    Compare {
        case: PathBuf,
        /// Comma-separated methods.
        #[arg(long, value_delimiter = ',', value_parser = method, default_value = "neumann,gauss-seidel,gmres,bicgstab,direct")]
        methods: Vec<Method>,
        /// Output HDF5 file (default: `<case>-compare.h5`).
        #[arg(short, long)]
        output: Option<PathBuf>,
        /// Convergence plot (default: beside the output, `<output>.png`).
        #[arg(long)]
        plot: Option<PathBuf>,
        #[command(flatten)]
        discretize: Discretize,
        #[command(flatten)]
        stopping: Stopping,
        #[command(flatten)]
        basis: cli::basis::BasisOptions,
        /// Instead of methods, compare angular bases (`full`, `sh:L`, `svd:R`), each solved
        /// with the first of --methods, against the full angular solution.
        #[arg(long, value_delimiter = ',', conflicts_with = "basis")]
        bases: Vec<String>,
        /// Also trace a forward Monte Carlo estimate of the field with this many photons
        /// and show every method's agreement with it (in standard errors).
        #[arg(long, allow_negative_numbers = true)]
        photons: Option<u64>,
        /// Seed of that estimate.
        #[arg(long, allow_negative_numbers = true, default_value_t = 1)]
        seed: u64,
        #[command(flatten)]
        kernel: cli::kernel::KernelOptions,
    },
    /// Monte Carlo references: backward path tracing of cameras (mean and standard-error
    /// EXR images, cd/m²) and probes or, with --forward, light tracing into the (patch, cell)
    /// bins (HDF5).
    Trace {
        /// The case file (TOML).
        case: PathBuf,
        /// Trace only this camera (repeatable; default: every camera of the case).
        #[arg(long = "camera")]
        cameras: Vec<String>,
        /// Paths per pixel (backward).
        #[arg(long, allow_negative_numbers = true, default_value_t = 64)]
        spp: usize,
        /// Paths per reading of each [[probe]] (backward).
        #[arg(long, allow_negative_numbers = true, default_value_t = 65_536)]
        probe_samples: usize,
        /// Forward light tracing into the (patch, direction cell) bins instead of cameras.
        #[arg(long)]
        forward: bool,
        /// Photons (forward).
        #[arg(long, allow_negative_numbers = true, default_value_t = 1_000_000)]
        photons: u64,
        /// Bin the photons (forward) on the patches and cells of this solution (an HDF5 file
        /// of `ugo solve` of the same case): the hierarchy's leaves, for `ugo agree` leaf by leaf.
        #[arg(long, value_name = "SOLUTION")]
        bins_of: Option<PathBuf>,
        /// Seed of the random streams: the same seed and counts give the same result.
        #[arg(long, allow_negative_numbers = true, default_value_t = 1)]
        seed: u64,
        /// Keep only light reflected at most this many times (a truncated Neumann sum).
        #[arg(long, allow_negative_numbers = true)]
        max_order: Option<usize>,
        /// Folder for the images (backward, default `.`) or the HDF5 file (forward,
        /// default `<case>-forward.h5`).
        #[arg(short, long)]
        output: Option<PathBuf>,
        #[command(flatten)]
        discretize: Discretize,
    },
    /// A solution against a Monte Carlo reference (forward HDF5 or traced EXR), in standard errors.
    Agree {
        /// The HDF5 file of a solve.
        solution: PathBuf,
        /// `ugo trace --forward`'s HDF5 file, or `ugo trace`'s mean image `X.exr` (with `X-stderr.exr`).
        reference: PathBuf,
        /// The camera of a traced image (default: the one camera of its size).
        #[arg(long)]
        camera: Option<String>,
        /// Stratified rays per pixel for rendering the solution.
        #[arg(long, allow_negative_numbers = true, default_value_t = 64)]
        samples: usize,
        /// Shading of the rendered solution (see `ugo render`).
        #[arg(long, value_enum, default_value_t = ShadingArg::Flat)]
        shading: ShadingArg,
        /// Final-gather rays per pixel (with --shading gather).
        #[arg(long, allow_negative_numbers = true, default_value_t = 256)]
        gather_rays: usize,
        /// Relative standard error up to which a forward bin is precise enough to read the
        /// solution's relative error off it (the leaf-by-leaf figures).
        #[arg(long, allow_negative_numbers = true, default_value_t = 5e-3)]
        precise: f64,
        /// Also write the signed relative difference (solution − reference)/reference per pixel
        /// as a PNG in false colour (against a traced image only).
        #[arg(long, value_name = "PNG")]
        difference: Option<PathBuf>,
        /// Where the difference image's colours saturate, ± percent.
        #[arg(long, value_name = "PERCENT", allow_negative_numbers = true, default_value_t = 5.0)]
        difference_scale: f64,
    },
    /// Camera images (linear EXR, tone-mapped PNG) of a solution written by `solve`.
    Render {
        /// The HDF5 file of a solve.
        solution: PathBuf,
        /// Render only this camera (repeatable; default: every camera of the stored scene).
        #[arg(long = "camera")]
        cameras: Vec<String>,
        /// Luminance shown as white in the PNG, cd/m² (default: the 99th percentile).
        #[arg(long, allow_negative_numbers = true)]
        exposure: Option<f64>,
        /// Folder for the images.
        #[arg(short, long, default_value = ".")]
        output: PathBuf,
        /// Also write a false-colour map with a legend in cd/m², on this scale.
        #[arg(long, value_enum, value_name = "SCALE")]
        false_colour: Option<ScaleArg>,
        /// Also write the reflection-order pictures for these recorded orders, side by side.
        #[arg(long, allow_negative_numbers = true, value_delimiter = ',')]
        orders: Vec<usize>,
        /// How a hit point is shaded.
        #[arg(long, value_enum, default_value_t = ShadingArg::Flat)]
        shading: ShadingArg,
        /// Final-gather rays per pixel (with `--shading gather`).
        #[arg(long, allow_negative_numbers = true, default_value_t = 64)]
        gather_rays: usize,
        /// Draw eigenvector J of K (1 = the dominant) from the file's /spectrum (`ugo norms
        /// --spectrum N`) instead of the field: its real part, with a signed false colour.
        #[arg(long, value_name = "J", conflicts_with_all = ["orders", "light_scene"])]
        mode: Option<usize>,
        /// Draw this light scene of the case (`[[light_scene]]`) instead of its own light.
        #[arg(long, value_name = "NAME")]
        light_scene: Option<String>,
        #[command(flatten)]
        view: cli::render::CameraOptions,
    },
    /// One self-contained HTML page of a solved case (docs/report.md): materials, luminaires,
    /// grids against their EN 12464-1 targets with their plans, glare, light scenes,
    /// daylight, the surfaces' illuminance and the warnings, read from the solution file alone.
    Report {
        /// The HDF5 file of a solve.
        solution: PathBuf,
        /// The HTML file (default: the solution's name with `.html`, beside it).
        #[arg(short, long)]
        output: Option<PathBuf>,
    },
    /// The UGR table of CIE 190 of a luminaire (IES or EULUMDAT): the 19 standard rooms
    /// viewed crosswise and endwise under the five reflectance combinations, for 1000 lm of
    /// lamp flux, with the summand for the luminaire's own (docs/photometry.md).
    Glare {
        /// The luminaire's photometric file (.ies or .ldt).
        #[arg(long, value_name = "LUMINAIRE")]
        table: PathBuf,
        /// Also write the table as CSV, one row per cell.
        #[arg(long)]
        csv: Option<PathBuf>,
        /// The spacing-to-height ratio of the luminaires' array (the catalogues' 0.25; CIE 190's examples use 1).
        #[arg(long, default_value_t = ugo::readout::ugr_table::CATALOGUE_SPACING)]
        spacing: f64,
    },
    /// Probes, grids, observers, cameras and light scenes of an edited case read on the
    /// field of a solve saved with --save-kernel: no assembly, no solve (each light scene a
    /// weighted sum of the stored groups' fields).
    Readout {
        /// The HDF5 file of a solve made with --save-kernel.
        solution: PathBuf,
        /// The case, edited (default: the case stored in the file); its geometry,
        /// discretization, materials, luminaires, emission and groups must be the solved ones.
        case: Option<PathBuf>,
        /// The output HDF5 file (default: the solution file itself, replaced when complete).
        #[arg(short, long)]
        output: Option<PathBuf>,
        #[command(flatten)]
        discretize: Discretize,
    },
    /// Patches, unknowns, and the kernel's estimated size, before any assembly.
    Info {
        case: PathBuf,
        #[command(flatten)]
        discretize: Discretize,
    },
    /// Throughput of every stage against the machine's limits (table and JSON).
    Bench(cli::bench::BenchOptions),
    /// Hard probes placed by class (room corners and edges, contacts, undersides, umbrae, the
    /// dimmest 5 %, open surfaces) as `[[probe]]` tables: the case with them is a benchmark
    /// (docs/accuracy.md).
    Probes {
        /// The case file (TOML).
        case: PathBuf,
        /// The file the `[[probe]]` tables go to.
        #[arg(short, long)]
        output: PathBuf,
        /// Probes per class (fewer where a room has no place for them).
        #[arg(long, allow_negative_numbers = true, default_value_t = 20)]
        count: usize,
        /// Seed of the candidates' random streams: the same seed gives the same probes.
        #[arg(long, allow_negative_numbers = true, default_value_t = 1)]
        seed: u64,
        /// Candidate points drawn at most.
        #[arg(long, allow_negative_numbers = true, default_value_t = 200_000)]
        candidates: usize,
        #[command(flatten)]
        discretize: Discretize,
    },
    /// K, I − K and L0 of a saved kernel (`solve --save-kernel`) as Matrix Market or PETSc binary files.
    Export(cli::export::ExportOptions),
}

fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) if e.use_stderr() => {
            eprint!("ugo: {}", e.render());
            return ExitCode::from(2);
        }
        Err(e) => e.exit(),
    };
    if let Err(e) = ugo::interrupt::install() {
        eprintln!("ugo: warning: SIGINT and SIGTERM are not handled ({e}): they stop at once");
    }
    if let Err(e) = ugo::io::survive_size_limit() {
        eprintln!("ugo: warning: SIGXFSZ is not handled ({e}): a write past the file-size limit ends the process");
    }
    let result = run(cli.command);
    if let Some(stop) = ugo::interrupt::requested(String::new) {
        match result {
            Ok(()) => {
                eprintln!("ugo: stopped by {} after every output was written", ugo::interrupt::signal_name(stop.signal))
            }
            Err(e) => eprintln!("ugo: stopped: {e:#}"),
        }
        return ExitCode::from(stop.exit_status());
    }
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("ugo: error: {e:#}");
            ExitCode::FAILURE
        }
    }
}

fn run(command: Command) -> anyhow::Result<()> {
    match command {
        Command::Solve {
            case, output, discretize, part: Some(part), method, orders, norms, kernel, linked, ..
        } => {
            if method.is_some() || orders.is_some() || norms || kernel.given() {
                anyhow::bail!(
                    "--part links one part's receivers and does not solve: --method, --orders, --norms, --save-kernel and --kernel-file do not apply"
                );
            }
            match linked.is_empty() {
                true => cli::part::run(&case, &discretize, part, output),
                false => cli::part::rows(&case, &discretize, part, &linked, output),
            }
        }
        Command::Parts { files } => cli::part::join_files(&files),
        Command::Solve {
            case, output, discretize, stopping, method, orders, norms, basis, kernel, part: None, ..
        } => {
            let methods = method.into_iter().collect();
            let run = study::Job { methods, orders, norms, basis: basis.choice()?, ..kernel.job() };
            cli::solve::run(&case, &discretize, Job { output, ..Job::new(run, stopping, "") })
        }
        Command::Norms { case, output, discretize, stopping, kernel, spectrum } => {
            let methods = match spectrum {
                Some(_) => vec![Method::Neumann, Method::Gmres { restart: RESTART }],
                None => vec![Method::Neumann],
            };
            let spectrum = spectrum.map(|n| n as usize);
            let run = study::Job { methods, norms: true, spectrum, ..kernel.job() };
            cli::solve::run(&case, &discretize, Job { output, ..Job::new(run, stopping, "-norms") })
        }
        Command::Compare { case, methods, output, plot, discretize, stopping, basis, bases, photons, seed, kernel } => {
            let stem = case.file_stem().unwrap_or_default().to_string_lossy().into_owned();
            if !bases.is_empty() && kernel.given() {
                anyhow::bail!(
                    "--kernel-file and --save-kernel do not apply to --bases (each basis assembles its own case)"
                );
            }
            if !bases.is_empty() {
                let plot = plot.unwrap_or_else(|| {
                    output.map_or(PathBuf::from(format!("{stem}-bases.png")), |o| o.with_extension("png"))
                });
                let params = SolveParams {
                    tolerance: stopping.tolerance.unwrap_or(1e-10),
                    max_iterations: stopping.max_iterations.unwrap_or(10_000),
                    ..SolveParams::default()
                };
                let method = methods.first().copied().unwrap_or(Method::Gmres { restart: RESTART });
                return cli::basis::study(&case, &discretize, &bases, method, params, &plot);
            }
            let output = output.unwrap_or_else(|| PathBuf::from(format!("{stem}-compare.h5")));
            let (plot, output) = (Some(plot.unwrap_or_else(|| output.with_extension("png"))), Some(output));
            let run = study::Job { methods, basis: basis.choice()?, photons, seed, ..kernel.job() };
            cli::solve::run(&case, &discretize, Job { output, plot, ..Job::new(run, stopping, "-compare") })
        }
        Command::Render {
            solution,
            cameras,
            exposure,
            output,
            false_colour,
            orders,
            shading,
            gather_rays,
            mode,
            light_scene,
            view,
        } => {
            let light_scene = light_scene.as_deref();
            let look = cli::render::Look {
                view,
                exposure,
                false_colour,
                orders: &orders,
                shading,
                gather_rays,
                mode,
                light_scene,
            };
            cli::render::run(&solution, &cameras, &output, &look)
        }
        Command::Trace {
            case,
            cameras,
            spp,
            probe_samples,
            forward,
            photons,
            bins_of,
            seed,
            max_order,
            output,
            discretize,
        } => {
            let options = ugo::trace::TraceOptions { seed, max_order };
            let photons = forward.then_some(photons);
            let job = cli::trace::TraceJob { cameras, spp, probe_samples, photons, bins_of, options, output };
            cli::trace::run(&case, &discretize, &job)
        }
        Command::Agree {
            solution,
            reference,
            camera,
            samples,
            shading,
            gather_rays,
            precise,
            difference,
            difference_scale,
        } => {
            let rendering = cli::agree::Rendering { camera: camera.as_deref(), samples, shading, gather_rays };
            let difference = difference.as_deref().map(|path| cli::agree::Difference { path, scale: difference_scale });
            cli::agree::run(&solution, &reference, &rendering, precise, difference.as_ref())
        }
        Command::Report { solution, output } => cli::report::run(&solution, output),
        Command::Glare { table, csv, spacing } => cli::glare_table::run(&table, csv, spacing),
        Command::Readout { solution, case, output, discretize } => {
            cli::readout::run(&solution, case.as_deref(), &discretize, output)
        }
        Command::Info { case, discretize } => cli::info::run(&case, &discretize),
        Command::Bench(options) => cli::bench::run(&options),
        Command::Export(options) => cli::export::run(&options),
        Command::Probes { case, output, count, seed, candidates, discretize } => {
            let options = ugo::placement::Options { count, seed, candidates };
            cli::probes::run(&case, &discretize, &cli::probes::ProbesJob { output, options })
        }
    }
}
