//! Exposed area (`docs/design.md` §3, "Contacts"): the part of a patch that lies outside every
//! solid. Furniture stands on floors and against walls; the part of a patch under a
//! cabinet's foot print sees only the cabinet's inside, so its share of `G` (through the
//! same stratified points, `occlusion::polygon_points`) is zero. The luminance a patch
//! receives and sends is that of its exposed part, spread over the exposed area `φ A`:
//! spread over all of `A`, the hidden part's share of every reflection would be lost.
//! `φ` of a patch across a foot print's edge is measured piece by piece, and the factor
//! `e = φ/φ̂` takes what its four points integrate to it ((3.11)).
//!
//! A point lies inside a solid when every ray from it into its hemisphere (along the
//! normal and four at 60° from it) meets the back of a one-sided surface, or touches a
//! surface lying on it (the floor under a block's bottom, the block's bottom on the
//! floor): the rays start a [`standoff`] behind the point, so that a surface in contact
//! is met within twice that distance.

use crate::geometry::{ConvexPolygon, Mesh, NO_TWIN, Patch};
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

    /// The exposed area of `patch`, m²: its area times the share of it that lies outside
    /// every solid, from its [`POINTS`] stratified points where they agree. A patch that
    /// straddles a solid's foot print is measured piece by piece: each piece whose points
    /// disagree is split in four (`ConvexPolygon::split`), down to [`EXPOSURE_LEVELS`]
    /// levels, so that a floor patch under a block's edge is not taken as a half or a
    /// quarter outside (the Cornell box's floor beside its tall block: 0.5 for 0.333 and
    /// 0.640, exact; 0.388 and 0.608 so). When none of its points is outside, its quarters are measured so: a sliver
    /// outside still takes the luminaires' light that lands on it, rather than losing it.
    pub fn exposed_area(&self, visibility: &Visibility, patch: &Patch) -> f64 {
        let outside = |x: &DVec3| self.outside(visibility, patch, *x);
        patch.area * outside_share(&patch.polygon, EXPOSURE_LEVELS, true, &outside)
    }
}

/// Levels of quarters down to which a straddling patch's exposed share is measured: its
/// smallest pieces have a sixteenth of its edge. A piece whose points agree is not split
/// again, so an edge across only its corner goes unseen: 5.5 and 3.2 % of the patch off on
/// the Cornell box's two patches above.
const EXPOSURE_LEVELS: usize = 4;

/// Share of `polygon` whose points `outside` accepts: of its [`POINTS`] stratified points
/// where they agree (or at the last level), else the area-weighted mean of its quarters'
/// shares. `first`: a polygon none of whose points is outside is still split once.
fn outside_share(polygon: &ConvexPolygon, levels: usize, first: bool, outside: &dyn Fn(&DVec3) -> bool) -> f64 {
    let open = polygon_points(polygon).iter().filter(|x| outside(x)).count();
    let agree = open == POINTS || (open == 0 && !first);
    if agree || levels == 0 {
        return open as f64 / POINTS as f64;
    }
    let quarters = polygon.split();
    let area: f64 = quarters.iter().map(ConvexPolygon::area).sum();
    quarters.iter().map(|q| q.area() * outside_share(q, levels - 1, false, outside)).sum::<f64>() / area
}

/// Per patch of `mesh`, the factor that takes an exchange area integrated through its
/// [`POINTS`] stratified points to its exposed area: `exposed / (A · share of those
/// points outside)`. A straddling patch's points see through its exposed part as if it
/// were that share of the patch; its exposed area is measured finer ([`Backs::exposed_area`]).
/// 1 where every point is outside, or none (such a patch exchanges nothing through its points).
pub fn point_corrections(mesh: &Mesh, visibility: &Visibility) -> Vec<f64> {
    let backs = Backs::of(mesh);
    mesh.patches
        .par_iter()
        .map(|p| {
            if p.exposed >= p.area * (1.0 - 1e-12) {
                return 1.0;
            }
            let open = polygon_points(&p.polygon).iter().filter(|x| backs.outside(visibility, p, **x)).count();
            if open == 0 { 1.0 } else { p.exposed / (p.area * open as f64 / POINTS as f64) }
        })
        .collect()
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
