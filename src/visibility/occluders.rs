//! Occluders: the large opaque convex pieces of the surfaces, which hide whole shafts.
//!
//! A surface is cut into convex pieces before it is meshed (`geometry::tessellate` at an
//! unbounded size: a rectangle, the pieces of a wall less its holes, the sides of a box, the
//! ears of a polygon), and every mesh of the scene, at any patch size and after any split of
//! its elements, tiles each such piece exactly. So when every segment from a point to a
//! convex polygon crosses one piece strictly inside its edges, no ray from the point
//! through the polygon gets past it ([`hides`], by convexity: the segments' crossings of the
//! piece's plane lie in the convex hull of the crossings of the segments to the polygon's
//! corners). Discs and spheres are left out (their pieces change with the patch size), and
//! so are imported meshes (their triangles are small, and a face would have to be matched
//! among all of them).
//!
//! The shaft of an opening seen from a point in another room is hidden by the wall between
//! them: `docs/daylight.md`, "Openings hidden behind a wall".
//!
//! And when every face lies on an occluder, the hull of a point and a polygon that no
//! occluder meets ([`Occluders::clear`], `hull.rs`) holds no face: every segment from the
//! point to the polygon is clear, without a ray (`between.rs`, a gather's pieces of a patch).
//! Only the occluders whose boxes meet the hull's box are tested (a binary BVH over the
//! boxes): a furnished office has 1,044 occluders, and testing each against every
//! piece of every gather cost three times the rays it saved (`docs/performance.md`,
//! "Readouts of many probes").

use super::hull::Hull;
use crate::geometry::{ConvexPolygon, Mesh, Shape, Surface, tessellate};
use glam::{DVec3, Vec3A};
use obvhs::{BvhBuildParams, aabb::Aabb, bvh2::Bvh2, bvh2::builder::build_bvh2};
use std::time::Duration;

/// A face that lies on no occluder.
const NONE: u32 = u32::MAX;

/// The occluders of a scene and the one each face of a mesh lies on.
#[derive(Clone)]
pub struct Occluders {
    pieces: Vec<ConvexPolygon>,
    of_face: Vec<u32>,
    /// The pieces' unit normals.
    normals: Vec<DVec3>,
    /// The pieces' boxes, grown by [`Occluders::margin`], in a binary BVH whose primitive
    /// indices are indices into `pieces`.
    boxes: Bvh2,
    /// How far every box is grown, m: the scene's round-off and the rays' slack
    /// (`Visibility`'s `epsilon`, 10⁻⁶ of the scene), tenfold.
    margin: f64,
    /// Every face lies on an occluder.
    complete: bool,
}

impl std::fmt::Debug for Occluders {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Occluders").field("pieces", &self.pieces.len()).field("complete", &self.complete).finish()
    }
}

impl Occluders {
    /// The occluders of `surfaces`, each face of `mesh` (meshed from them) matched to the
    /// one of its surface that holds its centroid.
    pub fn of(surfaces: &[Surface], mesh: &Mesh) -> Occluders {
        let mut pieces = Vec::new();
        let mut first = Vec::with_capacity(surfaces.len() + 1);
        for surface in surfaces {
            first.push(pieces.len());
            if matches!(
                surface.shape,
                Shape::Rectangle { .. } | Shape::Polygon { .. } | Shape::Holed { .. } | Shape::Box { .. }
            ) {
                pieces.extend(tessellate(&surface.shape, f64::INFINITY));
            }
        }
        first.push(pieces.len());
        let tolerance = 1e-9 * mesh.extent();
        let mut of_face = vec![NONE; mesh.faces];
        for patch in &mesh.patches {
            let s = patch.surface as usize;
            let slot = &mut of_face[patch.face as usize];
            if *slot == NONE {
                let holds = |k: &usize| lies_on(&pieces[*k], patch.centroid, tolerance);
                *slot = (first[s]..first[s + 1]).find(holds).map_or(NONE, |k| k as u32);
            }
        }
        let complete = of_face.iter().all(|&k| k != NONE);
        let normals = pieces.iter().map(ConvexPolygon::normal).collect();
        let margin = 1e-5 * mesh.extent();
        let grown: Vec<Aabb> = pieces.iter().map(|p| grown_box(p.vertices().iter().copied(), margin)).collect();
        let boxes = build_bvh2(&grown, BvhBuildParams::fast_build(), &mut Duration::default());
        Occluders { pieces, of_face, normals, boxes, margin, complete }
    }

    /// The occluder that `face` lies on, if any.
    pub fn of_face(&self, face: u32) -> Option<&ConvexPolygon> {
        let k = *self.of_face.get(face as usize)?;
        (k != NONE).then(|| &self.pieces[k as usize])
    }

    /// True when no face stands in the hull of `p` and the convex `polygon` (`p` in front of
    /// its plane): every face lies on an occluder and every occluder is apart from the hull
    /// (`Hull::apart`), `p` counting as on a plane within `near` (m) of it. False when
    /// one may, or `p` is not in front.
    /// Occluders whose grown box misses the hull's grown box are apart from it without a
    /// test: the two boxes are `2 margin` apart along an axis.
    pub fn clear(&self, p: DVec3, polygon: &ConvexPolygon, near: f64) -> bool {
        let Some(hull) = self.complete.then(|| Hull::of(p, polygon)).flatten() else { return false };
        let corners = std::iter::once(p).chain(polygon.vertices().iter().copied());
        let mut clear = true;
        self.boxes.aabb_traverse(grown_box(corners, self.margin), |bvh, id| {
            let node = &bvh.nodes[id as usize];
            let held = &bvh.primitive_indices[node.first_index as usize..][..node.prim_count as usize];
            clear = held.iter().all(|&k| hull.apart(&self.pieces[k as usize], self.normals[k as usize], near));
            clear
        });
        clear
    }
}

/// The box of `points` grown by `margin` (m) on every side, and outwards by the `f32`
/// rounding of its corners.
fn grown_box(points: impl Iterator<Item = DVec3>, margin: f64) -> Aabb {
    let (lo, hi) = points.fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(lo, hi), x| (lo.min(x), hi.max(x)));
    let (lo, hi) = (lo - DVec3::splat(margin), hi + DVec3::splat(margin));
    let round = |x: DVec3| DVec3::splat(1e-6) * x.abs();
    Aabb::new(Vec3A::from((lo - round(lo)).as_vec3()), Vec3A::from((hi + round(hi)).as_vec3()))
}

/// True when `x` lies in the plane of `piece` and inside it, within `tolerance` (m).
fn lies_on(piece: &ConvexPolygon, x: DVec3, tolerance: f64) -> bool {
    let n = piece.normal();
    let v = piece.vertices();
    (x - v[0]).dot(n).abs() <= tolerance && inside_by(piece, n, x, -tolerance)
}

/// True when `x` (in the plane of `piece`, unit normal `n`) lies at least `margin` (m)
/// inside every edge of it.
fn inside_by(piece: &ConvexPolygon, n: DVec3, x: DVec3, margin: f64) -> bool {
    let v = piece.vertices();
    (0..v.len()).all(|i| {
        let edge = v[(i + 1) % v.len()] - v[i];
        n.cross(edge).normalize_or_zero().dot(x - v[i]) >= margin
    })
}

/// True when every segment from `p` to a point of the convex `polygon` crosses `occluder` at
/// least `margin` (m) inside its edges, `p` and the polygon at least `margin` off its plane
/// on either side of it.
pub fn hides(occluder: &ConvexPolygon, p: DVec3, polygon: &ConvexPolygon, margin: f64) -> bool {
    let n = occluder.normal();
    let at = occluder.vertices()[0];
    let height = |x: DVec3| (x - at).dot(n);
    let hp = height(p);
    if hp.abs() <= margin {
        return false;
    }
    polygon.vertices().iter().all(|&v| {
        let hv = height(v);
        hv * hp.signum() < -margin && inside_by(occluder, n, p + (v - p) * (hp / (hp - hv)), margin)
    })
}
