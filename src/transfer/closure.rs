//! Closure (`docs/design.md` §3b, "Balance"): the share of a patch's hemisphere that the fronts
//! of surfaces cover, seen from its exposed part. It is `Σ_j F_ij` of the exact kernel,
//! the row sum every `G` must carry and, by reciprocity, the share of the patch's light
//! that lands on surfaces: 1 in a closed room, less where the patch sees an opening (or
//! the back of a one-sided surface). Estimated by rays: from each of the patch's
//! stratified points outside every solid (`exposure.rs`), [`DIRECTIONS`] cosine-distributed
//! directions in strata; a ray counts when it meets the front of a surface (or a two-sided
//! one). In a closed room every ray counts and the closure is exactly 1.

use super::exposure::{Backs, OUTSIDE_RAYS};
use crate::geometry::{Patch, cosine_direction};
use crate::transfer::occlusion::{POINTS, polygon_points};
use crate::visibility::Visibility;
use glam::DVec3;

/// Strata per side of the unit square of directions, per sample point.
const STRATA: usize = 4;
/// Directions per sample point.
pub const DIRECTIONS: usize = STRATA * STRATA;

/// The rays of one patch's closure: how many were cast and how many met a front.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Closure {
    /// Rays cast.
    pub cast: u32,
    /// Rays that met the front of a surface.
    pub covered: u32,
}

impl Closure {
    /// The estimate, `covered / cast`; 0 when no ray was cast (a patch inside solids).
    pub fn share(&self) -> f64 {
        if self.cast > 0 { self.covered as f64 / self.cast as f64 } else { 0.0 }
    }

    /// True when `value` is within three binomial standard errors of the estimate (at
    /// least one ray's worth): the rays cannot tell it from the closure. A patch whose
    /// every ray met a front accepts only 1.
    pub fn admits(&self, value: f64) -> bool {
        let (p, n) = (self.share(), self.cast as f64);
        if self.covered == self.cast {
            return value == 1.0;
        }
        (value - p).abs() <= (3.0 * (p * (1.0 - p) / n).sqrt()).max(1.0 / n)
    }
}

impl Backs {
    /// The closure rays of `patch` and every ray it took: from its stratified points
    /// outside every solid, or when none is, from those of its quarters (as
    /// `Backs::exposed_area` measures it); none for a patch wholly inside solids.
    pub fn closure(&self, visibility: &Visibility, patch: &Patch) -> (Closure, usize) {
        let (closure, tested) = self.closure_from(visibility, patch, &polygon_points(&patch.polygon));
        if closure.cast > 0 {
            return (closure, tested);
        }
        let finer: Vec<DVec3> = patch.polygon.split().iter().flat_map(polygon_points).collect();
        let (closure, more) = self.closure_from(visibility, patch, &finer);
        (closure, tested + more)
    }

    /// The closure rays from those of `points` on `patch` that lie outside every solid, and
    /// the rays that tested them.
    fn closure_from(&self, visibility: &Visibility, patch: &Patch, points: &[DVec3]) -> (Closure, usize) {
        let frame = patch.frame();
        let mut closure = Closure::default();
        for (k, &x) in points.iter().enumerate() {
            if !self.outside(visibility, patch, x) {
                continue;
            }
            let covered = (0..DIRECTIONS)
                .filter(|&s| {
                    let direction = frame.world(cosine_direction(stratum(s / STRATA, k), stratum(s % STRATA, k + 1)));
                    self.meets_a_front(visibility, patch, x, direction)
                })
                .count();
            // a point none of whose rays meets a front lies inside a solid after all (within
            // a standoff of its edge, where `outside`'s rays leave it): not part of the exposed
            // part, whose closure this is
            if covered > 0 {
                closure.cast += DIRECTIONS as u32;
                closure.covered += covered as u32;
            }
        }
        (closure, points.len() * (OUTSIDE_RAYS + DIRECTIONS))
    }
}

/// A point in stratum `i` of [`STRATA`], offset within it by sample point `k` (each point
/// covers the strata at a different place).
fn stratum(i: usize, k: usize) -> f64 {
    (i as f64 + ((k % POINTS) as f64 + 0.5) / POINTS as f64) / STRATA as f64
}
