//! `ugo bench` on the uniform kernel: the occlusion rays, the triad, the assembly's rate and
//! its speed-up over threads, the sparse product against the triad, the factored
//! operator's application and the scaling curve, printed and written as JSON, and the
//! peers' files of `--export`.

use super::json::write_json;
use super::layouts::occlusion_rays;
use super::options::BenchOptions;
use super::scaling;
use anyhow::{Context, Result};
use serde_json::json;
use ugo::kernel::Factored;
use ugo::model::Model;
use ugo::scene::Scene;
use ugo::study::bench::{self, Occlusion};

/// Measures `scene` on its uniform kernel.
pub fn run(o: &BenchOptions, scene: &Scene) -> Result<()> {
    let threads = rayon::current_num_threads();
    say!("ugo bench: {} ({} threads)", scene.name, threads);
    let occlusion = occlusion_rays(o, scene, scene.discretization.patch_size)?;

    let triad = bench::triad();
    say!("  memory bandwidth      {:>12.2} GB/s     (STREAM-like triad, 3 × 256 MiB)", triad / 1e9);

    let (full, model) = bench::step(scene, scene.discretization.patch_size)?;
    let pairs_rate = full.pairs as f64 / model.stats.kernel_seconds;
    say!(
        "  assembly              {:>12.3e} pairs/s  ({} facing pairs, {} occlusion rays in {:.2} s: {:.3e} rays/s)",
        pairs_rate,
        full.pairs,
        model.stats.rays,
        model.stats.kernel_seconds,
        model.stats.rays as f64 / model.stats.kernel_seconds
    );
    let g = &model.kernel.g;
    let (product, factored) = product_figures(&model, triad);

    let one = bench::assembly_with_threads(scene, 1)?;
    let all = full.assembly_seconds;
    say!(
        "  assembly speed-up     {:>12.2}×        (1 → {threads} threads, the whole model build: {one:.2} s → {all:.2} s)",
        one / all
    );

    let curve = bench::scaling(scene, &o.scaling, full)?;
    scaling::print(&curve);
    let traffic = product.bytes_per_second;
    let report = json!({
        "case": scene.name,
        "threads": threads,
        "occlusion_rays_per_second": occlusion.rays_per_second,
        "occlusion_rays_per_second_one_thread": occlusion.one_thread_rays_per_second,
        "link_rays_links_per_second_alone_one_thread": occlusion.links.alone_links_per_second,
        "link_rays_links_per_second_together_one_thread": occlusion.links.together_links_per_second,
        "link_rays_links": occlusion.links.links,
        "link_rays_rays": occlusion.links.rays,
        "triad_bytes_per_second": triad,
        "assembly_pairs_per_second": pairs_rate,
        "assembly_rays_per_second": model.stats.rays as f64 / model.stats.kernel_seconds,
        "spmv_bytes_per_second": traffic,
        "spmv_fraction_of_triad": traffic / triad,
        "bytes_per_nonzero": g.bytes() / g.nnz() as f64,
        "factored_apply_seconds": factored,
        "assembly_speedup": one / all,
        "scaling": curve.steps,
        "scaling_exponent": curve.exponent,
    });
    write_json(o, &report)?;
    if let Some(dir) = &o.export {
        let meta = json!({
            "ugo_occlusion_rays_per_second": occlusion.rays_per_second,
            "ugo_occlusion_rays_per_second_one_thread": occlusion.one_thread_rays_per_second,
            "ugo_spmv_seconds": product.seconds,
            "threads": threads
        });
        export_peers(dir, &occlusion, g, meta)?;
    }
    Ok(())
}

/// The rays, triangles and matrix for `docs/peers/peers.py`.
fn export_peers(
    dir: &std::path::Path,
    occlusion: &Occlusion,
    g: &ugo::kernel::Transport,
    meta: serde_json::Value,
) -> Result<()> {
    let g = g
        .as_double()
        .context("--export needs the uniform kernel (`--kernel uniform`) in double precision (--precision f64)")?;
    bench::export(dir, &occlusion.mesh, &occlusion.visibility, &occlusion.segments, g, meta)?;
    say!("  exported              {} (run docs/peers/peers.py {})", dir.display(), dir.display());
    Ok(())
}

/// The sparse product `G x` and the factored `K x` (seconds), printed against the triad's
/// bandwidth `triad`.
fn product_figures(model: &Model, triad: f64) -> (bench::SparseProduct, f64) {
    let g = &model.kernel.g;
    let product = bench::sparse_product(g);
    let traffic = product.bytes_per_second;
    say!(
        "  sparse product G x    {:>12.2} GB/s     ({:.0} % of the triad; {} non-zeros, {:.1} B each ({}), {:.2} ms)",
        traffic / 1e9,
        100.0 * traffic / triad,
        g.nnz(),
        g.bytes() / g.nnz() as f64,
        g.precision().name(),
        product.seconds * 1e3
    );
    let factored = bench::apply_seconds(&Factored::new(&model.kernel));
    say!(
        "  factored K x = B(G x) {:>12.2} ms       ({:.3e} unknowns/s)",
        factored * 1e3,
        model.l0.len() as f64 / factored
    );
    (product, factored)
}
