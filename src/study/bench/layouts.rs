//! Every BVH layout of `ugo bench --layouts` on the same segments (binary or compressed
//! wide BVH, obvhs build preset, scene turned by a generic rotation or not), with a
//! correctness figure: the axis-aligned rays, one dropped onto every patch along its
//! normal, that failed to find that patch ("lost").

use super::occlusion::Segment;
use crate::geometry::Mesh;
use crate::visibility::{BuildPreset, NO_FACE, Visibility, VisibilityOptions};
use rayon::prelude::*;
use std::time::Instant;

/// One layout measured.
#[derive(Debug, Clone, Copy)]
pub struct Layout {
    /// The layout.
    pub options: VisibilityOptions,
    /// Seconds to build it.
    pub build_seconds: f64,
    /// Occlusion rays per second through it (all threads of the current pool).
    pub rays_per_second: f64,
    /// Share of the segments found visible, %.
    pub visible: f64,
    /// Rays dropped onto a patch along its normal that did not find it.
    pub lost: usize,
}

/// Every layout on `segments`, measured one at a time as the iterator is read: binary
/// then wide, each with the fast, medium and slow presets, each unrotated then rotated.
pub fn layouts<'a>(mesh: &'a Mesh, segments: &'a [Segment]) -> impl Iterator<Item = Layout> + 'a {
    [false, true].into_iter().flat_map(move |wide| {
        [BuildPreset::Fast, BuildPreset::Medium, BuildPreset::Slow].into_iter().flat_map(move |preset| {
            [false, true]
                .into_iter()
                .map(move |rotate| layout(mesh, segments, VisibilityOptions { wide, rotate, preset }))
        })
    })
}

/// One layout built over `mesh` and timed on `segments`.
fn layout(mesh: &Mesh, segments: &[Segment], options: VisibilityOptions) -> Layout {
    let t = Instant::now();
    let v = Visibility::build_with(mesh, options);
    let build_seconds = t.elapsed().as_secs_f64();
    let t = Instant::now();
    let seen: usize = segments.par_iter().map(|(a, b, f)| v.visible(*a, *b, *f) as usize).sum();
    let rays_per_second = segments.len() as f64 / t.elapsed().as_secs_f64();
    let lost = mesh
        .patches
        .par_iter()
        .filter(|p| {
            let hit = v.closest_hit(p.centroid + 1e-3 * p.normal, -p.normal, NO_FACE);
            hit.is_none_or(|h| h.face != p.face)
        })
        .count();
    let visible = 100.0 * seen as f64 / segments.len() as f64;
    Layout { options, build_seconds, rays_per_second, visible, lost }
}
