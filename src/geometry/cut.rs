//! Cuts (`docs/design.md` §3b, "Cuts"): an edge of one face carried onto the plane of
//! another, along whose line the hierarchy splits that plane's elements instead of at their
//! middles (`kernel/hierarchy/cuts.rs` finds them; `kernel/hierarchy/tree.rs` splits by them).

use super::polygon::ConvexPolygon;
use glam::DVec3;

/// A cut nearer than this to an element's edge, m, leaves the element to its usual split:
/// its edge lies on the line already.
pub const CUT_LEAST: f64 = 1e-3;

/// An edge carried onto an element's plane: the element splits along the edge's line
/// where the edge lies beside it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cut {
    /// One end of the edge, m.
    pub point: DVec3,
    /// Its other end, m.
    pub end: DVec3,
    /// The unit normal of the plane through the edge across the element's plane.
    pub normal: DVec3,
}

impl Cut {
    /// True when the edge lies beside `polygon` along its line: the polygon's vertices,
    /// projected on the line, reach within [`CUT_LEAST`] of the edge. An edge's line is cut
    /// only where the edge is (a desk's foot cuts the floor beside it, not across the room).
    pub fn beside(&self, polygon: &ConvexPolygon) -> bool {
        let length = self.point.distance(self.end);
        let along = (self.end - self.point) / length;
        let (lo, hi) = polygon.vertices().iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
            let s = (*v - self.point).dot(along);
            (lo.min(s), hi.max(s))
        });
        hi > -CUT_LEAST && lo < length + CUT_LEAST
    }

    /// `polygon` in strips along the one of `cuts` that crosses it nearest its middle,
    /// beside its edge (`ConvexPolygon::split_along`), if one does.
    pub fn split(polygon: &ConvexPolygon, cuts: &[Cut]) -> Option<[ConvexPolygon; 4]> {
        let along =
            cuts.iter().filter(|c| c.beside(polygon)).filter_map(|c| polygon.split_along(c.point, c.normal, CUT_LEAST));
        along.min_by(|a, b| (a.0 - 0.5).abs().total_cmp(&(b.0 - 0.5).abs())).map(|(_, pieces)| pieces)
    }
}
