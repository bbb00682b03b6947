//! The section of a mesh by a plane: the segments where its patches cross the plane, as a
//! plan draws the furniture and walls a work plane cuts (`docs/rendering.md`, grid plans).
//! A vertex on the plane counts as in front of it, so a patch lying in the plane, or
//! touching it along an edge from the front, has no section, while one that reaches the
//! plane from behind (a desk's side under a grid at the height of its top) is cut at
//! its edge. Of two back-to-back patches only the first is cut.

use super::{ConvexPolygon, Mesh, NO_TWIN};
use glam::DVec3;

/// The segments where the patches of `mesh` cross the plane through `point` of unit
/// normal `normal`, m.
pub fn section(mesh: &Mesh, point: DVec3, normal: DVec3) -> Vec<[DVec3; 2]> {
    mesh.patches
        .iter()
        .enumerate()
        .filter(|(i, p)| p.twin == NO_TWIN || p.twin as usize > *i)
        .filter_map(|(_, p)| cut(&p.polygon, point, normal))
        .collect()
}

/// The segment where the convex `polygon` crosses the plane, if it does.
fn cut(polygon: &ConvexPolygon, point: DVec3, normal: DVec3) -> Option<[DVec3; 2]> {
    let v = polygon.vertices();
    let height = |x: DVec3| (x - point).dot(normal);
    let mut ends = v.iter().zip(v.iter().cycle().skip(1)).filter_map(|(&a, &b)| {
        let (ha, hb) = (height(a), height(b));
        ((ha < 0.0) != (hb < 0.0)).then(|| a + (b - a) * (ha / (ha - hb)))
    });
    Some([ends.next()?, ends.next()?])
}
