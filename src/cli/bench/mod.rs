//! `ugo bench`: the throughput of every stage next to the machine's limit, as a table
//! and as JSON (issue 9, `docs/performance.md`): occlusion rays per second (all BVH
//! layouts with `--layouts`), form-factor pairs per second during assembly and its
//! speed-up from one thread to all, the sparse product in GB/s of matrix traffic against
//! a STREAM-like triad measured in the same run, the time per application of the
//! factored operator, and assemble-and-solve time and peak memory over several patch
//! sizes with the fitted growth exponent. `--export DIR` writes the same rays and matrix
//! for the peers (Embree, scipy). With `--kernel hierarchical` it measures the rays, the
//! operator's application and the hierarchy's curve over leaf sizes (`--patch-size`) instead:
//! leaves, links, rays and time against N with their fitted exponents (`hierarchy.rs`).

mod bandwidth;
mod export;
mod hierarchy;
mod layouts;
mod peak;
mod scaling;

use super::load;
use super::options::Discretize;
use anyhow::{Context, Result, bail};
use serde_json::json;
use std::path::PathBuf;
use ugo::kernel::Factored;
use ugo::model::Model;
use ugo::scene::{Hierarchical, KernelKind, Scene};
use ugo::visibility::Visibility;

/// What `ugo bench` measures.
#[derive(Debug, clap::Args)]
pub struct BenchOptions {
    /// The case to measure on (default: the bundled Cornell box).
    #[arg(default_value = "cases/cornell-box.toml")]
    case: PathBuf,
    #[command(flatten)]
    discretize: Discretize,
    /// Occlusion rays to time.
    #[arg(long, default_value_t = 2_000_000)]
    rays: usize,
    /// Also time every BVH layout (with a correctness column).
    #[arg(long)]
    layouts: bool,
    /// Patch sizes of the scaling curve, m (default: 2.5, 2, 1.5 and 1.25 times the case's);
    /// with `--kernel hierarchical`, the leaves' patch sizes under the same roots (default:
    /// 4, 2.8, 2 and 1.4 times the case's).
    #[arg(long, value_delimiter = ',')]
    scaling: Vec<f64>,
    /// Also time dense LU (faer against nalgebra) at these sizes.
    #[arg(long, value_delimiter = ',')]
    lu: Vec<usize>,
    /// Write the figures as JSON here.
    #[arg(long)]
    json: Option<PathBuf>,
    /// Write the rays, triangles and matrix for `docs/peers/peers.py` into this folder.
    #[arg(long)]
    export: Option<PathBuf>,
}

pub fn run(o: &BenchOptions) -> Result<()> {
    for &n in &o.lu {
        layouts::dense_lu(n);
    }
    let scene = load(&o.case, &o.discretize)?;
    // Refused before meshing, from the surfaces, like `solve` (`kernel::forecast`).
    Model::forecast(&scene).check(scene.discretization.memory_limit)?;
    if let Some(json) = &o.json {
        super::check_writable(json)?;
    }
    if let KernelKind::Hierarchical(h) = scene.discretization.kernel {
        return run_hierarchical(o, &scene, h);
    }
    let threads = rayon::current_num_threads();
    println!("ugo bench: {} ({} threads)", scene.name, threads);
    let (mesh, visibility, segments, rays) = occlusion(o, &scene, scene.discretization.patch_size)?;

    let triad = bandwidth::triad();
    println!("  memory bandwidth      {:>12.2} GB/s     (STREAM-like triad, 3 × 256 MiB)", triad / 1e9);

    let (full, model) = scaling::step(&scene, scene.discretization.patch_size)?;
    let pairs_rate = full.pairs as f64 / model.stats.kernel_seconds;
    println!(
        "  assembly              {:>12.3e} pairs/s  ({} facing pairs, {} occlusion rays in {:.2} s: {:.3e} rays/s)",
        pairs_rate,
        full.pairs,
        model.stats.rays,
        model.stats.kernel_seconds,
        model.stats.rays as f64 / model.stats.kernel_seconds
    );
    let g = &model.kernel.g;
    let (spmv, traffic, factored) = product_figures(&model, triad);

    let one = scaling::assembly_with_threads(&scene, 1)?;
    let all = full.assembly_seconds;
    println!(
        "  assembly speed-up     {:>12.2}×        (1 → {threads} threads, the whole model build: {one:.2} s → {all:.2} s)",
        one / all
    );

    let (steps, exponent) = scaling_curve(&scene, &o.scaling, full)?;
    let report = json!({
        "case": scene.name,
        "threads": threads,
        "occlusion_rays_per_second": rays,
        "triad_bytes_per_second": triad,
        "assembly_pairs_per_second": pairs_rate,
        "assembly_rays_per_second": model.stats.rays as f64 / model.stats.kernel_seconds,
        "spmv_bytes_per_second": traffic,
        "spmv_fraction_of_triad": traffic / triad,
        "bytes_per_nonzero": g.bytes() / g.nnz() as f64,
        "factored_apply_seconds": factored,
        "assembly_speedup": one / all,
        "scaling": steps,
        "scaling_exponent": exponent,
    });
    write_json(o, &report)?;
    if let Some(dir) = &o.export {
        export_peers(
            dir,
            &mesh,
            &visibility,
            &segments,
            g,
            json!({ "ugo_occlusion_rays_per_second": rays, "ugo_spmv_seconds": spmv, "threads": threads }),
        )?;
    }
    Ok(())
}

/// `ugo bench --kernel hierarchical`: the occlusion rays on the roots, the operator's
/// application and the hierarchy's curve over leaf sizes (`--scaling`); the figures of a
/// stored matrix (its sparse product against the triad, `--export`) do not apply.
fn run_hierarchical(o: &BenchOptions, scene: &Scene, h: Hierarchical) -> Result<()> {
    let tolerance = h.link_tolerance;
    if o.export.is_some() {
        bail!(
            "--export writes the stored matrix G for the peers; the hierarchical kernel stores none (use --kernel uniform)"
        );
    }
    let threads = rayon::current_num_threads();
    println!("ugo bench: {} ({} threads, hierarchical kernel, roots of {} m)", scene.name, threads, h.root_size);
    let rays = occlusion(o, scene, h.root_size)?.3;
    let (own, model) = hierarchy::level(scene, scene.discretization.patch_size)?;
    println!("  sparse product G x    skipped: the hierarchy stores no matrix (links applied by pull, gather, push)");
    let factored = bandwidth::apply_seconds(&Factored::new(&model.kernel));
    println!(
        "  factored K x = B(G x) {:>12.2} ms       ({:.3e} unknowns/s; {} links, {:.1} MiB)",
        factored * 1e3,
        model.l0.len() as f64 / factored,
        model.stats.pairs,
        model.kernel.g.bytes() / (1u64 << 20) as f64
    );
    let curve = hierarchy::curve(scene, tolerance, &o.scaling, own)?;
    let report = json!({
        "case": scene.name,
        "threads": threads,
        "assembly": "hierarchical",
        "root_size": h.root_size,
        "link_tolerance": tolerance,
        "occlusion_rays_per_second": rays,
        "factored_apply_seconds": factored,
        "hierarchy": curve.levels,
        "links_exponent": curve.links_exponent,
        "time_exponent": curve.time_exponent,
        "skipped": ["spmv_bytes_per_second", "triad_bytes_per_second", "assembly_speedup", "scaling", "export"],
    });
    write_json(o, &report)
}

/// The uniform mesh at `size`, its ray caster, `--rays` segments between facing patches and
/// the occlusion rays per second through them, printed (with every layout for `--layouts`).
fn occlusion(
    o: &BenchOptions,
    scene: &Scene,
    size: f64,
) -> Result<(ugo::geometry::Mesh, Visibility, Vec<layouts::Segment>, f64)> {
    let mesh = ugo::geometry::Mesh::build(&scene.surfaces, size);
    let segments = facing_segments(o, &mesh)?;
    let visibility = Visibility::build(&mesh);
    let rays = layouts::rays_per_second(&visibility, &segments).max(layouts::rays_per_second(&visibility, &segments));
    println!(
        "  occlusion rays        {rays:>12.3e} rays/s   ({} patches, {} rays, default BVH)",
        mesh.len(),
        segments.len()
    );
    if o.layouts {
        layouts::all_layouts(&mesh, &segments);
    }
    Ok((mesh, visibility, segments, rays))
}

/// Writes `report` to `--json`, if given.
fn write_json(o: &BenchOptions, report: &serde_json::Value) -> Result<()> {
    if let Some(path) = &o.json {
        ugo::io::write_bytes(path, serde_json::to_string_pretty(report)?.as_bytes())?;
        println!("  json                  {}", path.display());
    }
    Ok(())
}

/// Assembly and solve at several patch sizes (`sizes`, default 2.5, 2, 1.5 and 1.25 times
/// the case's) beside the case's own `full` step, printed, with the fitted exponent of time
/// against the number of patches.
fn scaling_curve(scene: &Scene, sizes: &[f64], full: scaling::Step) -> Result<(Vec<scaling::Step>, f64)> {
    let sizes = if sizes.is_empty() {
        [2.5, 2.0, 1.5, 1.25].map(|f| f * scene.discretization.patch_size).to_vec()
    } else {
        sizes.to_vec()
    };
    let mut steps = Vec::new();
    for h in sizes {
        steps.push(scaling::step(scene, h)?.0);
    }
    steps.push(full);
    steps.sort_by_key(|s| s.patches);
    let exponent = scaling::exponent(&steps);
    println!("  scaling (assemble + solve, Neumann to 1e-8), time ∝ N^{exponent:.2}");
    println!(
        "    {:>10} {:>9} {:>11} {:>11} {:>10} {:>9} {:>11}",
        "patch m", "patches", "pairs", "non-zeros", "assembly s", "solve s", "+peak MiB"
    );
    for s in &steps {
        let peak = s.peak_bytes.map_or("-".into(), |b| format!("{:.0}", b / (1u64 << 20) as f64));
        println!(
            "    {:>10.4} {:>9} {:>11} {:>11} {:>10.2} {:>9.3} {:>11}",
            s.patch_size, s.patches, s.pairs, s.nonzeros, s.assembly_seconds, s.solve_seconds, peak
        );
    }
    Ok((steps, exponent))
}

/// `--rays` segments between facing patches, or a clear refusal when no patches face.
fn facing_segments(o: &BenchOptions, mesh: &ugo::geometry::Mesh) -> Result<Vec<layouts::Segment>> {
    let Some(segments) = layouts::segments(mesh, o.rays) else {
        bail!(
            "{}: no two of its {} patches face each other, so there are no occlusion rays or kernel entries \
             to time; bench a case with interreflection (e.g. cases/cornell-box.toml)",
            o.case.display(),
            mesh.len()
        );
    };
    Ok(segments)
}

/// The rays, triangles and matrix for `docs/peers/peers.py`.
fn export_peers(
    dir: &std::path::Path,
    mesh: &ugo::geometry::Mesh,
    visibility: &Visibility,
    segments: &[layouts::Segment],
    g: &ugo::kernel::Transport,
    meta: serde_json::Value,
) -> Result<()> {
    let g = g
        .as_double()
        .context("--export needs the uniform kernel (`--kernel uniform`) in double precision (--precision f64)")?;
    export::export(dir, mesh, visibility, segments, g, meta)?;
    println!("  exported              {} (run docs/peers/peers.py {})", dir.display(), dir.display());
    Ok(())
}

/// The sparse product `G x` (seconds, bytes/s) and the factored `K x` (seconds), printed
/// against the triad's bandwidth `triad`.
fn product_figures(model: &Model, triad: f64) -> (f64, f64, f64) {
    let g = &model.kernel.g;
    let spmv = bandwidth::spmv_seconds(g);
    let traffic = g.bytes() / spmv;
    println!(
        "  sparse product G x    {:>12.2} GB/s     ({:.0} % of the triad; {} non-zeros, {:.1} B each ({}), {:.2} ms)",
        traffic / 1e9,
        100.0 * traffic / triad,
        g.nnz(),
        g.bytes() / g.nnz() as f64,
        g.precision().name(),
        spmv * 1e3
    );
    let factored = bandwidth::apply_seconds(&Factored::new(&model.kernel));
    println!(
        "  factored K x = B(G x) {:>12.2} ms       ({:.3e} unknowns/s)",
        factored * 1e3,
        model.l0.len() as f64 / factored
    );
    (spmv, traffic, factored)
}
