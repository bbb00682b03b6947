//! What a point sees of the pieces of one face (a gather's shadow cutting,
//! `transfer::occlusion::cut_along_shadows`; `docs/design.md` (5.2), the visibility
//! `V(p, P_j)`): whether the segment from the point to a point of the face crosses no other
//! face, and whether no face at all stands in the hull of the point and a whole piece
//! (`Visibility::hull_is_clear`, by the occluders), so that the piece's rays, which would
//! all see, need not be traced.

use super::shaft::Sight;
use super::{Blocker, Visibility};
use crate::geometry::ConvexPolygon;
use glam::DVec3;
use std::cell::Cell;

/// The pieces of a face seen from a point, both lying on the faces `ignore` (the point's,
/// or none, and the pieces'); its rays try the triangle that blocked the worker's last one
/// first (`last`, one cell per worker: `Visibility::visible_shared`).
pub struct SightTo<'a> {
    visibility: &'a Visibility,
    p: DVec3,
    ignore: [u32; 2],
    last: &'a Cell<Blocker>,
}

impl<'a> SightTo<'a> {
    /// What `p` sees of the points on the faces of `ignore` (its own and theirs).
    pub fn new(visibility: &'a Visibility, p: DVec3, ignore: [u32; 2], last: &'a Cell<Blocker>) -> SightTo<'a> {
        SightTo { visibility, p, ignore, last }
    }
}

impl Sight for SightTo<'_> {
    fn sees(&self, x: DVec3) -> bool {
        self.visibility.visible_shared(self.p, x, self.ignore, self.last)
    }

    fn clear(&self, piece: &ConvexPolygon) -> bool {
        self.visibility.hull_is_clear(self.p, piece)
    }

    fn hidden(&self, _: &ConvexPolygon, _: &mut usize) -> bool {
        false
    }
}
