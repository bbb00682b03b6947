//! The hull of a point and a convex polygon in front of it, and whether a convex occluder
//! stands apart from it (`occluders.rs`, `Occluders::clear`): when none does, every segment
//! from the point to the polygon is clear, and a gather's piece is seen whole without its
//! rays (`between.rs`; `docs/design.md` (5.2), the visibility `V(p, P_j)`). The
//! answer must be the rays' own (`docs/performance.md`, "Readouts of many probes"): the
//! separating planes are exact but for round-off ([`TOUCHING`]), and segments so flat that
//! the rays' `f32` and edge slack may find a face at their ends are left to the rays
//! ([`GRAZING`]).

use crate::geometry::{ConvexPolygon, MAX_CLIPPED};
use glam::DVec3;

/// A segment that leaves a plane, or arrives at one, at a sine below this can be found
/// crossing a face of that plane, or one sharing an edge with it, a few µm from its end: the
/// rays work in `f32` with a slack on the triangles' edges, and along a segment at a sine of
/// 0.018 an error of 0.1 µm across it is one of 5 µm along it, beyond the rays' shortening
/// (`Visibility`, 10⁻⁶ of the scene). Such a segment is traced, not known clear, so that
/// the hull's answers are the rays' own.
const GRAZING: f64 = 0.2;

/// A point within this share of `near` of a separating plane, on the wrong side, counts as
/// on it: the round-off of points on one plane (a patch's corners on its face, a piece's on
/// the floor under a block), not a real crossing. The rays' own answers for points a few
/// `near` inside a face are theirs (a floor piece's centre 2 µm under a block's side is
/// hidden by it), so no more is allowed.
const TOUCHING: f64 = 1e-3;

/// The hull of a point and a convex polygon in front of it, as the planes that bound it.
pub(super) struct Hull<'a> {
    apex: DVec3,
    corners: &'a [DVec3],
    /// `(outward unit normal, a point)`: the polygon's plane, then one through the apex and
    /// each edge.
    planes: [(DVec3, DVec3); MAX_CLIPPED + 1],
    count: usize,
}

impl<'a> Hull<'a> {
    /// The hull of `p` and `polygon`; none when `p` sees a corner of it at a sine below
    /// [`GRAZING`] from its plane (a segment arriving that flat by an edge the polygon shares
    /// with another face is found to cross that face, within the rays' slack along it).
    pub(super) fn of(p: DVec3, polygon: &'a ConvexPolygon) -> Option<Hull<'a>> {
        let (normal, corners) = (polygon.normal(), polygon.vertices());
        if corners.iter().any(|&v| (p - v).dot(normal) < GRAZING * p.distance(v)) {
            return None;
        }
        let mut planes = [(DVec3::ZERO, DVec3::ZERO); MAX_CLIPPED + 1];
        planes[0] = (-normal, corners[0]);
        let mut count = 1;
        for outward in edge_sides(p, corners) {
            planes[count] = (outward, p);
            count += 1;
        }
        Some(Hull { apex: p, corners, planes, count })
    }

    /// True when a plane separates the convex `occluder` (unit normal `n`) from the hull,
    /// each within [`TOUCHING`] `near` of its side: the occluder's plane or one of the
    /// hull's; but never when the apex lies within `near` (m) of the occluder's plane and
    /// a corner is seen from it closer to that plane than [`GRAZING`].
    pub(super) fn apart(&self, occluder: &ConvexPolygon, n: DVec3, near: f64) -> bool {
        let at = occluder.vertices()[0];
        let height = |x: DVec3| (x - at).dot(n);
        if height(self.apex).abs() <= near
            && self.corners.iter().any(|&v| height(v).abs() < GRAZING * v.distance(self.apex))
        {
            return false;
        }
        let touching = TOUCHING * near;
        let heights = || std::iter::once(self.apex).chain(self.corners.iter().copied()).map(height);
        if heights().all(|h| h >= -touching) || heights().all(|h| h <= touching) {
            return true;
        }
        let beyond =
            |&(outward, on): &(DVec3, DVec3)| occluder.vertices().iter().all(|&o| (o - on).dot(outward) >= -touching);
        self.planes[..self.count].iter().any(beyond)
    }
}

/// The outward unit normals of the planes through `apex` and each edge of the convex
/// polygon `corners` (not containing the apex); an edge seen end-on gives none.
pub(super) fn edge_sides(apex: DVec3, corners: &[DVec3]) -> impl Iterator<Item = DVec3> + '_ {
    let centroid = corners.iter().sum::<DVec3>() / corners.len() as f64;
    corners.iter().enumerate().filter_map(move |(i, &a)| {
        let b = corners[(i + 1) % corners.len()];
        let side = (a - apex).cross(b - apex).normalize_or_zero();
        (side != DVec3::ZERO).then(|| if side.dot(centroid - apex) < 0.0 { side } else { -side })
    })
}
