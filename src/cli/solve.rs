//! `ugo solve`, `ugo norms` and `ugo compare`: the case and the options turned into a
//! `study::Job`, the solve (`study::solve_case`), the HDF5 file, the CSV files and plot
//! beside it, and the printed summary and tables.

use super::options::{Discretize, Stopping};
use super::{Bars, bytes, check_writable, describe, file_name, load};
use anyhow::{Context, Result, bail};
use std::path::{Path, PathBuf};
use ugo::geometry::{Mesh, section};
use ugo::io::{
    MonteCarlo, OutputLock, Overlay, Run, Solution, Warning, convergence_plot, one_line, told, write_daylight_map,
    write_grid_csv, write_grid_map, write_probes_csv, write_solution,
};
use ugo::luminaire::Source;
use ugo::model::HierarchyRecord;
use ugo::readout::daylight::DaylightReadings;
use ugo::readout::grid::GridReading;
use ugo::readout::grid_error::GridErrorBars;
use ugo::readout::probe::ProbeReading;
use ugo::scene::{LightScene, Scene};
use ugo::solve::norms::{Estimate, Estimator, Norms};
use ugo::solve::orders::OrderRecord;
use ugo::solve::{Method, SolveParams};
use ugo::study::{self, solve_case};

/// Most partial sums `--orders` keeps (each is a copy of the field).
const MAX_ORDERS_KEPT: usize = 64;

/// What one command asks: the solve (its stopping rule from the command line or the
/// case) and where its files go.
pub struct Job {
    pub run: study::Job,
    pub stopping: Stopping,
    pub output: Option<PathBuf>,
    /// Suffix of the default output name (`cornell-box{suffix}.h5`).
    pub suffix: &'static str,
    pub plot: Option<PathBuf>,
}

impl Job {
    /// The solve `run`, the output named `<case>{suffix}.h5`, no plot.
    pub fn new(run: study::Job, stopping: Stopping, suffix: &'static str) -> Job {
        Job { run, stopping, output: None, suffix, plot: None }
    }
}

pub fn run(case: &Path, d: &Discretize, job: Job) -> Result<()> {
    let scene = load(case, d)?;
    let strict = job.stopping.strict;
    if strict && let Some(first) = scene.warnings().first() {
        bail!("--strict: the case's warning is an error: {first}");
    }
    let params = SolveParams {
        tolerance: job.stopping.tolerance.unwrap_or(scene.solver.tolerance),
        max_iterations: job.stopping.max_iterations.unwrap_or(scene.solver.max_iterations),
        memory_limit: scene.discretization.memory_limit,
        ..SolveParams::default()
    };
    if !(params.tolerance > 0.0 && params.tolerance < 1.0) {
        bail!("--tolerance must lie in (0, 1), got {}", params.tolerance);
    }
    if let Some(orders) = &job.run.orders
        && orders.len() > MAX_ORDERS_KEPT
    {
        bail!("--orders keeps a copy of the field per order: at most {MAX_ORDERS_KEPT} orders, got {}", orders.len());
    }
    let stem = case.file_stem().unwrap_or_default().to_string_lossy().into_owned();
    let output = job.output.clone().unwrap_or_else(|| PathBuf::from(format!("{stem}{}.h5", job.suffix)));
    check_writable(&output)?;
    let _lock = OutputLock::take(&output)?;
    if let Some(plot) = &job.plot {
        check_writable(plot)?;
    }
    let study = study::Job { params, strict, ..job.run };
    let outputs: Vec<&Path> = std::iter::once(output.as_path()).chain(job.plot.as_deref()).collect();
    let s = solve_case(&scene, &study, &Bars::default())
        .map_err(|e| super::stop::not_written(super::size_key::located(e, case, d, &scene), &outputs))?;
    for (method, e) in &s.failures {
        eprintln!("ugo: {} failed: {e}", method.name());
    }
    let (notes, warnings): (Vec<&Warning>, Vec<&Warning>) = s.warnings.iter().partition(|w| w.is_note());
    for line in told(&warnings, job.stopping.verbose) {
        eprintln!("ugo: warning: {line}");
    }
    for line in told(&notes, job.stopping.verbose) {
        eprintln!("ugo: note: {line}");
    }
    if !warnings.is_empty() && !job.stopping.verbose {
        eprintln!("ugo: the whole text of every warning: --verbose, or /warnings in {}", output.display());
    }
    write_solution(&output, &scene, &s).with_context(|| format!("writing {}", output.display()))?;
    summary(&scene, &s, &output);
    super::kernel::print_record(&s.kernel);
    let names: Vec<String> = scene.surfaces.iter().map(|s| s.name.clone()).collect();
    let files = GridFiles { sources: &s.model.sources, mesh: &s.model.mesh, surfaces: &names };
    let stem = output.with_extension("").display().to_string();
    write_grids(&s.grids, &s.grid_errors, &stem, &files, s.daylight.as_ref())?;
    if !s.probes.is_empty() {
        let csv = super::beside(&output, "-probes.csv");
        write_probes_csv(&csv, &s.probes, s.daylight.as_ref())?;
        say!("  probes             {}", csv.display());
    }
    super::glare_grid::report(&s.glare_grids, &output, "  ")?;
    if let Some(light) = &s.light_scenes {
        let lit = |grids: &[GridReading], errors: &[GridErrorBars], stem: &str, light_scene: &LightScene| {
            let dimmed = study::dimmed(&scene, &s.model.sources, light_scene);
            write_grids(grids, errors, stem, &GridFiles { sources: &dimmed, ..files }, None)
        };
        super::light_scenes::report(light, &scene.lighting.scenes, &output, &lit)?;
    }
    if let Some(orders) = &s.orders {
        print_orders(orders, &s.x);
    }
    if let Some(norms) = &s.norms {
        print_norms(norms, &params, &s.runs);
    }
    if let Some(spectrum) = &s.spectrum {
        super::spectrum::report(spectrum, &s.runs, &output, &scene.name)?;
    }
    if s.runs.len() > 1 || s.monte_carlo.is_some() {
        print_comparison(&s.runs, s.monte_carlo.as_ref());
    }
    if let Some(plot) = &job.plot {
        convergence_plot(plot, &format!("{}: convergence of every method", scene.name), &s.runs)?;
        say!("  plot               {}", plot.display());
    }
    if strict && !warnings.is_empty() {
        bail!(
            "--strict: {} warning(s) about the solved field (the solution is written with them to {}): {}",
            warnings.len(),
            output.display(),
            warnings.iter().map(|w| one_line(&w.to_string())).collect::<Vec<_>>().join("; ")
        );
    }
    Ok(())
}

/// The hierarchical kernel's line of the summary and one line per refinement pass.
fn print_hierarchy(assembly: f64, rays: usize, h: &HierarchyRecord) {
    let leaves = h.census.leaf_level.len();
    let links: usize = h.census.element_links.iter().sum::<usize>() + h.census.cluster_links;
    say!(
        "  assembly           {assembly:>12.3} s   (hierarchical, link tolerance {:.0e}, roots {} m, leaves down to {} m: {} roots → {leaves} leaves, {links} links ({} with clusters, {} with segments blocked), {rays} occlusion rays)",
        h.parameters.link_tolerance,
        h.parameters.root_size,
        h.patch_size,
        h.roots,
        h.census.cluster_links,
        h.census.partial
    );
    for p in &h.history {
        let balanced = p.balance.map_or(String::new(), |b| {
            format!(
                "; balanced to the leaves' closures: correction {:.1e}, {} sweeps, row error {:.0e}",
                b.max_correction, b.iterations, b.residual
            )
        });
        say!(
            "    pass {}            {:>12.3} s   ({} links refined, {} leaves split along the direct light; {} links, {} leaves, ε {:.2e} cd/m²; operator {:.3} s, solve {:.3} s{balanced})",
            p.pass,
            p.seconds,
            p.refined,
            p.source_splits,
            p.links,
            p.leaves,
            p.epsilon,
            p.operator_seconds,
            p.solve_seconds
        );
    }
}

fn summary(scene: &Scene, s: &Solution, output: &Path) {
    let m = &s.model;
    let st = &m.stats;
    let g = &m.kernel.g;
    say!("ugo: {} ({})", scene.name, scene.path.display());
    say!("  patches N          {:>12}", m.mesh.len());
    say!("  direction cells K  {:>12}   ({})", m.kernel.cells(), m.kernel.directions.name());
    say!("  unknowns           {:>12}", g.rows());
    say!("  non-zeros of G     {:>12}   ({}, {})", g.nnz(), bytes(g.bytes()), g.precision().name());
    let assembly = st.mesh_seconds + st.bvh_seconds + st.kernel_seconds + st.light_seconds;
    match (&st.balance, &m.hierarchy) {
        (Some(b), _) => say!(
            "  assembly           {assembly:>12.3} s   ({} pairs, {} occlusion rays, balanced by {}: correction {:.1e}, {} sweeps, row error {:.0e})",
            st.pairs,
            st.rays,
            if b.by_cell { "cell" } else { "patch" },
            b.max_correction,
            b.iterations,
            b.residual
        ),
        (None, Some(h)) => print_hierarchy(assembly, st.rays, h),
        (None, None) => say!("  assembly           {assembly:>12.3} s   ({} occlusion rays)", st.rays),
    }
    say!("    of it direct light {:>8.3} s   (the sources' light on the patches: L0)", st.light_seconds);
    let i = s.info();
    say!(
        "  solve              {:>12.3} s   ({}, {} iterations, residual {:.2e})",
        i.seconds,
        i.method,
        i.iterations,
        i.residual()
    );
    if let Some((factors, full_residual)) = &s.basis {
        say!(
            "  basis              {:>12}   ({} coefficients per patch, rank {}; residual of the field in the full system {:.2e})",
            factors.basis.name(),
            factors.m,
            factors.rank,
            full_residual
        );
    }
    let e = &s.energy;
    if !m.sources.is_empty() {
        say!("  luminaires               emitted lm   on surfaces lm");
        for ((source, emitted), landed) in m.sources.iter().zip(&e.luminaire_emitted).zip(&m.direct.intercepted) {
            say!("    {:<22} {emitted:>12.4} {landed:>16.4}   {}", source.name, describe(source));
        }
    }
    say!("  flux emitted       {:>12.4} lm", e.emitted);
    say!("  flux absorbed      {:>12.4} lm", e.absorbed);
    say!("  flux escaped       {:>12.4} lm", e.escaped);
    match e.emitted {
        0.0 => say!("  imbalance          {:>12.3e} lm (nothing emitted)", e.imbalance),
        emitted => say!("  imbalance          {:>12.3e} (relative to emitted)", e.imbalance / emitted),
    }
    let warnings = s.warnings.iter().filter(|w| !w.is_note()).count();
    if warnings > 0 {
        say!("  warnings           {warnings:>12}   (on stderr and in /warnings)");
    }
    print_probes(&s.probes);
    super::glare::report(s.glare(), &s.grids, "  ");
    if let Some(d) = s.daylight.as_ref() {
        super::daylight::report(d, &s.probes, &s.grids);
    }
    say!("  written            {}", output.display());
}

/// The probes' readings, a line each; shared with `ugo readout`.
pub(super) fn print_probes(probes: &[ProbeReading]) {
    if !probes.is_empty() {
        say!("  probes                   luminance cd/m²   illuminance lx   error bar lx   of it direct lx");
        for p in probes {
            let bar = p.error.map_or("-".to_string(), |e| format!("± {e:.3}"));
            say!("    {:<22} {:>15.4} {:>16.4} {:>14} {:>17.4}", p.name, p.luminance, p.illuminance, bar, p.direct);
        }
    }
}

/// What every grid's files are drawn with: the sources (dimmed as the light scene has
/// them), the mesh whose section by each grid's plane the plan draws, and the surfaces'
/// names.
pub(super) struct GridFiles<'a> {
    pub(super) sources: &'a [Source],
    pub(super) mesh: &'a Mesh,
    pub(super) surfaces: &'a [String],
}

/// Each grid's statistics with their error bars (`errors`, one per grid), its CSV and plan
/// (`ugo::io::write_grid_map`), `<stem>-<grid>.{csv,png}`, and under a `[sky]` its daylight
/// factor's (or ratio's) plan `<stem>-<grid>-DF.png` (`-DR`); the points left out of the
/// statistics counted after them.
pub(super) fn write_grids(
    grids: &[GridReading],
    errors: &[GridErrorBars],
    stem: &str,
    files: &GridFiles,
    daylight: Option<&DaylightReadings>,
) -> Result<()> {
    if grids.is_empty() {
        return Ok(());
    }
    let head = ("grids", "E_avg lx", "± δ", "E_min lx", "± δ", "E_max lx", "U0 ± δ");
    say!("  {:<24} {:>12}   {:<8} {:>12}   {:<8} {:>12} {:>7}", head.0, head.1, head.2, head.3, head.4, head.5, head.6);
    for (i, (g, bars)) in grids.iter().zip(errors).enumerate() {
        let st = g.stats();
        let left_out = match g.left_out() {
            0 => String::new(),
            n => format!("   ({n} of {} points left out)", g.points.len()),
        };
        say!(
            "    {:<22} {:>12.4} ± {:<8.3} {:>12.4} ± {:<8.3} {:>12.4} {:>7.4} ± {:.4}{left_out}",
            g.grid.name,
            st.average,
            bars.average,
            st.min,
            bars.min,
            st.max,
            st.u0,
            bars.u0
        );
        let base = format!("{stem}-{}", file_name(&g.grid.name));
        let (csv, png) = (PathBuf::from(format!("{base}.csv")), PathBuf::from(format!("{base}.png")));
        let df = daylight.map(|d| (d.symbol(), d.grid_factor(i)));
        let df = df.as_ref().map(|(x, values)| (*x, values.as_slice()));
        write_grid_csv(&csv, g, bars, files.surfaces, df)?;
        let section = section(files.mesh, g.grid.origin, g.grid.normal);
        let overlay = Overlay { sources: files.sources, section: &section };
        write_grid_map(&png, g, &overlay)?;
        say!("      {}\n      {}", csv.display(), png.display());
        if let Some((symbol, values)) = df {
            let png = PathBuf::from(format!("{base}-{symbol}.png"));
            write_daylight_map(&png, g, values, symbol, &overlay)?;
            say!("      {}", png.display());
        }
    }
    Ok(())
}

fn print_norms(n: &Norms, params: &SolveParams, runs: &[Run]) {
    let observed =
        runs.iter().find(|r| r.method == Method::Neumann).map_or("-".to_string(), |r| r.info.iterations.to_string());
    match &n.matrix_free {
        None => say!("  norms of K"),
        Some(refused) => {
            say!("  norms of K, matrix-free (exact for K ≥ 0): {}", refused.figures());
            say!("    ‖K‖₁ = max Kᵀ·1 and ‖K‖∞ = max K·1 on the factored operator");
        }
    }
    say!("    ‖K‖₁             {:>12.6}", n.one);
    say!("    ‖K‖∞             {:>12.6}", n.infinity);
    match (n.frobenius, n.two) {
        (Some(frobenius), Some(two)) => {
            say!("    ‖K‖_F            {frobenius:>12.6}");
            say!("    ‖K‖₂             {:>12.6}   ({})", two.value, iterations(&two));
        }
        _ => {
            say!("    ‖K‖_F            not computed (it needs every entry of K)");
            say!(
                "    ‖K‖₂             not computed (power iteration on KᵀK); ρ(K) ≤ ‖K‖₂ ≤ √(‖K‖₁‖K‖∞) = {:.6}",
                n.two_bound()
            );
        }
    }
    let r = &n.spectral_radius;
    say!("    ρ(K)             {:>12.6}   ({})", r.value, iterations(r));
    say!("    cond∞(I − K)     {:>12.4}", n.condition_infinity);
    say!(
        "    Neumann iterations to {:.0e}: predicted {:.1}, observed {observed}",
        params.tolerance,
        n.predicted_iterations(params.tolerance)
    );
}

fn iterations(e: &Estimate) -> String {
    let by = match e.by {
        Estimator::Power => "power iterations",
        Estimator::Arnoldi => "products with K by Arnoldi",
    };
    format!("{} {by}{}", e.iterations, converged(e.converged))
}

fn print_orders(orders: &OrderRecord, x: &[f64]) {
    let l0 = orders.term_norms[0];
    say!("  reflection orders  ‖KⁿL0‖/‖L0‖, and the partial sum's distance from the solution ‖x − Σ_(m≤n) KᵐL0‖/‖x‖");
    let norm = |v: &mut dyn Iterator<Item = f64>| v.map(|e| e * e).sum::<f64>().sqrt();
    let scale = norm(&mut x.iter().copied());
    for (n, sum) in &orders.partial_sums {
        let deficit = norm(&mut sum.iter().zip(x).map(|(s, x)| x - s)) / scale;
        say!("    n = {n:<4} term {:>10.3e}   distance {:>10.3e}", orders.term_norms[*n] / l0, deficit);
    }
}

fn converged(ok: bool) -> &'static str {
    if ok { "" } else { ", NOT converged" }
}

fn print_comparison(runs: &[Run], mc: Option<&MonteCarlo>) {
    let extra =
        if mc.is_some() { format!(" {:>8} {:>8} {:>11}", "rms z", "max |z|", "rel. L1") } else { String::new() };
    say!(
        "  {:<14} {:>10} {:>13} {:>10} {:>12} {:>14}{extra}",
        "method",
        "iterations",
        "applications",
        "time s",
        "residual",
        "max rel. diff"
    );
    for (n, r) in runs.iter().enumerate() {
        let i = &r.info;
        let extra = mc.map_or(String::new(), |mc| {
            let a = &mc.agreements[n];
            format!(" {:>8.3} {:>8.2} {:>11.3e}", a.rms_z, a.max_abs_z, a.relative_l1)
        });
        say!(
            "  {:<14} {:>10} {:>13} {:>10.3} {:>12.2e} {:>14.2e}{extra}",
            r.method.name(),
            i.iterations,
            i.applications,
            i.seconds,
            i.residual(),
            r.difference
        );
    }
    if let Some(mc) = mc {
        say!(
            "  {:<14} {:>10} {:>13} {:>10.3}   (z: each method against this forward Monte Carlo estimate, \
             {} photons)",
            "forward MC",
            "-",
            "-",
            mc.seconds,
            mc.photons
        );
    }
}
