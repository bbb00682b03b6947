//! Bounding boxes of the scene's shapes (their coarsest meshes): for the plausibility of
//! lengths (`plausible.rs`) and the floor plan of a `work_plane` grid (`grid.rs`).

use crate::geometry::{Shape, Surface, tessellate};
use glam::DVec3;

/// A bounding box `(lo, hi)`.
#[derive(Clone, Copy)]
pub(super) struct Bounds(pub(super) DVec3, pub(super) DVec3);

impl Bounds {
    const EMPTY: Bounds = Bounds(DVec3::INFINITY, DVec3::NEG_INFINITY);

    fn union(self, o: Bounds) -> Bounds {
        Bounds(self.0.min(o.0), self.1.max(o.1))
    }
}

/// The bounding box `(low, high)` of every surface, m.
pub(super) fn surfaces_bounds(surfaces: &[Surface]) -> (DVec3, DVec3) {
    shapes_bounds(surfaces.iter().map(|s| &s.shape))
}

/// The bounding box `(low, high)` of `shapes`, m (`low > high` when there are none).
pub(super) fn shapes_bounds<'a>(shapes: impl Iterator<Item = &'a Shape>) -> (DVec3, DVec3) {
    let whole = shapes.fold(Bounds::EMPTY, |b, shape| b.union(bounds(shape)));
    (whole.0, whole.1)
}

/// The bounding box of a shape's coarsest mesh.
pub(super) fn bounds(shape: &Shape) -> Bounds {
    let mut b = Bounds::EMPTY;
    for e in tessellate(shape, f64::INFINITY) {
        for &v in e.vertices() {
            b = b.union(Bounds(v, v));
        }
    }
    b
}
