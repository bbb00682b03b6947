//! The visibility and dense-LU figures of `ugo bench`, printed: the occlusion rays through
//! the default BVH, every BVH layout on the same segments (`--layouts`) with its build
//! time, rate, share visible and rays lost, and the dense LU of `--lu` in faer against
//! nalgebra.

use super::options::BenchOptions;
use anyhow::{Context, Result};
use ugo::scene::Scene;
use ugo::study::bench::{self, DenseLu, Occlusion};

/// The occlusion rays through the uniform mesh at `size`, printed (with every layout for
/// `--layouts`); a case without facing patches is refused, named.
pub fn occlusion_rays(o: &BenchOptions, scene: &Scene, size: f64) -> Result<Occlusion> {
    let occlusion = Occlusion::measure(scene, size, o.rays).with_context(|| o.case.display().to_string())?;
    say!(
        "  occlusion rays        {:>12.3e} rays/s   ({} patches, {} rays, default BVH; {:.3e} rays/s on one thread, \
         the per-core figure docs/peers/peers.py sets against Embree's)",
        occlusion.rays_per_second,
        occlusion.mesh.len(),
        occlusion.segments.len(),
        occlusion.one_thread_rays_per_second
    );
    let l = &occlusion.links;
    say!(
        "  link shadow rays      {:>12.3e} links/s  (their segments traced together; {:.3e} links/s one by one, {:.2}×; \
         {} links, {} rays, one thread)",
        l.together_links_per_second,
        l.alone_links_per_second,
        l.together_links_per_second / l.alone_links_per_second,
        l.links,
        l.rays
    );
    if o.layouts {
        print_layouts(&occlusion);
    }
    Ok(occlusion)
}

/// Every layout on the occlusion's segments, a row printed as each is measured.
fn print_layouts(occlusion: &Occlusion) {
    say!(
        "  {:<8} {:<7} {:<7} {:>10} {:>14} {:>9} {:>6}",
        "bvh",
        "preset",
        "rotated",
        "build ms",
        "rays/s",
        "visible",
        "lost"
    );
    for l in bench::layouts(&occlusion.mesh, &occlusion.segments) {
        let name = if l.options.wide { "cwbvh" } else { "bvh2" };
        let (preset, rotate) = (format!("{:?}", l.options.preset), l.options.rotate);
        let (build, rate, visible, lost) = (l.build_seconds * 1e3, l.rays_per_second, l.visible, l.lost);
        say!("  {name:<8} {preset:<7} {rotate:<7} {build:>10.1} {rate:>14.3e} {visible:>8.1}% {lost:>6}");
    }
}

/// One size of dense LU, a line.
pub fn print_dense_lu(lu: &DenseLu) {
    let (n, faer_seconds, nalgebra_seconds, flops) = (lu.n, lu.faer_seconds, lu.nalgebra_seconds, lu.flops());
    say!(
        "dense LU n = {n}: faer {faer_seconds:.3} s ({:.1} GFLOP/s, residual {:.1e}), nalgebra {nalgebra_seconds:.3} s ({:.1} GFLOP/s, residual {:.1e})",
        flops / faer_seconds / 1e9,
        lu.faer_residual,
        flops / nalgebra_seconds / 1e9,
        lu.nalgebra_residual
    );
}
