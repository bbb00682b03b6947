//! `ugo bench --kernel hierarchical` (issue 14, point 6; `docs/design.md` §3b): the occlusion
//! rays on the roots, the operator's application and the hierarchy's curve over leaf sizes
//! (`--scaling`), printed as a table with the fitted exponents; the figures of a stored
//! matrix (its sparse product against the triad, `--export`) do not apply.

use super::json::write_json;
use super::layouts::occlusion_rays;
use super::options::BenchOptions;
use anyhow::{Result, bail};
use serde_json::json;
use ugo::kernel::Factored;
use ugo::scene::{Hierarchical, Scene};
use ugo::study::bench::{self, Curve};

/// Measures the hierarchical `scene` with roots and link tolerance `h`.
pub fn run(o: &BenchOptions, scene: &Scene, h: Hierarchical) -> Result<()> {
    let tolerance = h.link_tolerance;
    if o.export.is_some() {
        bail!(
            "--export writes the stored matrix G for the peers; the hierarchical kernel stores none (use --kernel uniform)"
        );
    }
    let threads = rayon::current_num_threads();
    say!("ugo bench: {} ({} threads, hierarchical kernel, roots of {} m)", scene.name, threads, h.root_size);
    let occlusion = occlusion_rays(o, scene, h.root_size)?;
    let (own, model) = bench::level(scene, scene.discretization.patch_size)?;
    say!("  sparse product G x    skipped: the hierarchy stores no matrix (links applied by pull, gather, push)");
    let factored = bench::apply_seconds(&Factored::new(&model.kernel));
    say!(
        "  factored K x = B(G x) {:>12.2} ms       ({:.3e} unknowns/s; {} links, {:.1} MiB)",
        factored * 1e3,
        model.l0.len() as f64 / factored,
        model.stats.pairs,
        model.kernel.g.bytes() / (1u64 << 20) as f64
    );
    let curve = bench::curve(scene, &o.scaling, own)?;
    print(&curve, tolerance);
    let report = json!({
        "case": scene.name,
        "threads": threads,
        "assembly": "hierarchical",
        "root_size": h.root_size,
        "link_tolerance": tolerance,
        "occlusion_rays_per_second": occlusion.rays_per_second,
        "occlusion_rays_per_second_one_thread": occlusion.one_thread_rays_per_second,
        "link_rays_links_per_second_alone_one_thread": occlusion.links.alone_links_per_second,
        "link_rays_links_per_second_together_one_thread": occlusion.links.together_links_per_second,
        "link_rays_links": occlusion.links.links,
        "link_rays_rays": occlusion.links.rays,
        "factored_apply_seconds": factored,
        "hierarchy": curve.levels,
        "links_exponent": curve.links_exponent,
        "time_exponent": curve.time_exponent,
        "skipped": ["spmv_bytes_per_second", "triad_bytes_per_second", "assembly_speedup", "scaling", "export"],
    });
    write_json(o, &report)
}

/// The curve as a table.
fn print(c: &Curve, tolerance: f64) {
    say!(
        "  hierarchy (link tolerance {tolerance:e}; refine + solve, Neumann to 1e-8): links ∝ N^{:.2}, time ∝ N^{:.2}",
        c.links_exponent,
        c.time_exponent
    );
    say!(
        "    {:>10} {:>6} {:>8} {:>10} {:>9} {:>9} {:>11} {:>7} {:>8} {:>8} {:>8} {:>8} {:>8} {:>9}",
        "patch size",
        "roots",
        "leaves N",
        "links",
        "links/N²",
        "nodes",
        "rays",
        "passes",
        "refine s",
        "link s",
        "op s",
        "solve s",
        "op MiB",
        "+peak MiB"
    );
    let mib = |b: f64| b / (1u64 << 20) as f64;
    for l in &c.levels {
        let peak = l.peak_bytes.map_or("-".into(), |b| format!("{:.0}", mib(b)));
        say!(
            "    {:>9.4} {:>6} {:>8} {:>10} {:>9.2e} {:>9} {:>11} {:>7} {:>8.2} {:>8.2} {:>8.2} {:>8.3} {:>8.1} {:>9}",
            l.patch_size,
            l.roots,
            l.leaves,
            l.links,
            l.links_per_n2,
            l.nodes,
            l.rays,
            l.passes,
            l.refinement_seconds,
            l.linking_seconds,
            l.operator_seconds,
            l.solve_seconds,
            mib(l.operator_bytes),
            peak
        );
    }
}
