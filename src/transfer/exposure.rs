//! Exposed area (`docs/design.md` §3, "Contacts"): the part of a patch that lies outside every
//! solid. Furniture stands on floors and against walls; the part of a patch under a
//! cabinet's foot print sees only the cabinet's inside, so its share of `G` (through the
//! same stratified points, `occlusion::polygon_points`) is zero. The luminance a patch
//! receives and sends is that of its exposed part, spread over the exposed area `φ A`:
//! spread over all of `A`, the hidden part's share of every reflection would be lost.
//!
//! A point lies inside a solid when every ray from it into its hemisphere (along the
//! normal and four at 60° from it) meets the back of a one-sided surface, or touches a
//! surface lying on it (the floor under a block's bottom, the block's bottom on the
//! floor): the rays start a [`standoff`] behind the point, so that a surface in contact
//! is met within twice that distance.

use crate::geometry::{Mesh, NO_TWIN, Patch};
use crate::progress::Progress;
use crate::transfer::occlusion::{POINTS, polygon_points};
use crate::visibility::{Visibility, standoff};
use glam::DVec3;
use rayon::prelude::*;

/// Which side of every face is its back: the normal of a one-sided face's patch, zero for
/// a two-sided face (which has no back); and the distance within which faces touch, m.
#[derive(Debug, Clone)]
pub struct Backs {
    normal: Vec<DVec3>,
    contact: f64,
}

impl Backs {
    /// The backs of the faces of `mesh` and its contact distance.
    pub fn of(mesh: &Mesh) -> Backs {
        let mut normal = vec![DVec3::ZERO; mesh.faces];
        for p in mesh.patches.iter().filter(|p| p.twin == NO_TWIN) {
            normal[p.face as usize] = p.normal;
        }
        Backs { normal, contact: standoff(mesh) }
    }

    /// True when the first face along the unit `direction` from `x` on `patch` shows it
    /// its back or touches `x`.
    fn blocked(&self, visibility: &Visibility, patch: &Patch, x: DVec3, direction: DVec3) -> bool {
        let cos = direction.dot(patch.normal);
        let behind = x - patch.normal * self.contact;
        visibility.closest_hit(behind, direction, patch.face).is_some_and(|hit| {
            hit.distance <= 2.0 * self.contact / cos || self.normal[hit.face as usize].dot(direction) > 0.0
        })
    }

    /// True when `x` on `patch` lies outside every solid: some ray of its hemisphere (the
    /// normal and four at 60°) neither meets a back nor touches `x`.
    pub fn outside(&self, visibility: &Visibility, patch: &Patch, x: DVec3) -> bool {
        let (c, s) = TILT;
        let frame = patch.frame();
        let tilted = [(s, 0.0), (0.0, s), (-s, 0.0), (0.0, -s)].map(|(a, b)| frame.world(DVec3::new(a, b, c)));
        !std::iter::once(patch.normal).chain(tilted).all(|d| self.blocked(visibility, patch, x, d))
    }

    /// True when the first face along the unit `direction` from `x` on `patch` (which lies
    /// outside every solid) shows it its front, or is two-sided.
    pub fn meets_a_front(&self, visibility: &Visibility, patch: &Patch, x: DVec3, direction: DVec3) -> bool {
        visibility
            .closest_hit(x, direction, patch.face)
            .is_some_and(|hit| self.normal[hit.face as usize].dot(direction) <= 0.0)
    }

    /// The exposed area of `patch`, m²: its area times the share of its [`POINTS`]
    /// stratified points that lie outside every solid. When all of them lie inside, the
    /// share of the `POINTS²` points of its four quarters: a sliver outside still takes
    /// the luminaires' light that lands on it, rather than losing it.
    pub fn exposed_area(&self, visibility: &Visibility, patch: &Patch) -> f64 {
        let outside = |x: &DVec3| self.outside(visibility, patch, *x);
        let open = polygon_points(&patch.polygon).iter().filter(|x| outside(x)).count();
        if open > 0 {
            return patch.area * open as f64 / POINTS as f64;
        }
        let finer = patch.polygon.split().iter().flat_map(polygon_points).filter(outside).count();
        patch.area * finer as f64 / (POINTS * POINTS) as f64
    }
}

/// Rays [`Backs::outside`] casts at most.
pub const OUTSIDE_RAYS: usize = 5;

/// Rays' angle from the normal, besides the normal itself: (cos 60°, sin 60°).
const TILT: (f64, f64) = (0.5, 0.866_025_403_784_438_6);

/// Patches measured between two reports to `progress` and two looks for a signal.
const CHUNK: usize = 4096;

/// Sets the exposed area of every patch of `mesh`, whose ray caster is `visibility`, as the
/// stage "exposed areas" of `progress` (a mesh of 10⁶ patches casts up to 8·10⁷ rays). A
/// signal's stop leaves the rest at their whole area (`crate::interrupt`: the caller
/// checks).
pub fn measure_exposure(mesh: &mut Mesh, visibility: &Visibility, progress: &dyn Progress) {
    let backs = Backs::of(mesh);
    progress.begin("exposed areas", mesh.patches.len() as u64);
    mesh.patches.par_chunks_mut(CHUNK).for_each(|chunk| {
        if crate::interrupt::asked() {
            return;
        }
        for p in chunk.iter_mut() {
            p.exposed = backs.exposed_area(visibility, p);
        }
        progress.advance(chunk.len() as u64);
    });
    progress.end();
}
