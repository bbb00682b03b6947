//! Shafts: whether any face can stop a ray from a point through a convex polygon in front
//! of it (an opening seen from a receiving point), so that those rays need not be traced
//! when none can (`docs/daylight.md`, "The openings' light at a luminaire's cost").
//!
//! The shaft from the apex `p` (receiving side facing the unit `n`) through the part of the
//! polygon in front of `p`, and on beyond it (what lies outside an opening, an overhang or a
//! facing building, stops the rays as well as what lies inside), is bounded by the plane of
//! `p` and the planes through `p` and each edge of the polygon. A box or a triangle that lies wholly on the
//! outer side of one of these planes, or on it, cannot meet the shaft's inside; whatever is
//! not so separated is taken to be in the way, so the test is conservative: the caller then
//! traces its rays. The boxes are those of a binary BVH over the same triangles, built on
//! the first query (the ray queries' wide BVH has no such traversal).

use super::hull::edge_sides;
use super::occluders::hides;
use super::{Blocker, NO_BLOCKER, Visibility};
use crate::geometry::{ConvexPolygon, MAX_CLIPPED};
use glam::{DVec3, Vec3A};
use obvhs::{BvhBuildParams, bvh2::Bvh2, bvh2::builder::build_bvh2_from_tris, triangle::Triangle};
use std::cell::Cell;
use std::time::Duration;

/// The binary BVH of the shaft queries over `triangles`, whose primitive indices are
/// indices into `triangles`.
fn shaft_tree(triangles: &[Triangle]) -> Bvh2 {
    build_bvh2_from_tris(triangles, BvhBuildParams::fast_build(), &mut Duration::default())
}

/// Nodes a shaft query holds to visit at most.
const STACK: usize = 128;

/// A bounding plane of a shaft: points with `normal · x ≥ offset` are outside or on it.
#[derive(Debug, Clone, Copy)]
struct Plane {
    normal: Vec3A,
    offset: f32,
}

impl Plane {
    /// The plane through `at` with the outward unit `normal`, moved inwards by `slack` (m).
    fn new(normal: DVec3, at: DVec3, slack: f64) -> Plane {
        Plane { normal: Vec3A::from(normal.as_vec3()), offset: (normal.dot(at) - slack) as f32 }
    }

    fn beyond(&self, x: Vec3A) -> bool {
        self.normal.dot(x) >= self.offset
    }

    /// True when the box `[min, max]` lies wholly outside or on the plane.
    fn beyond_box(&self, min: Vec3A, max: Vec3A) -> bool {
        let nearest = Vec3A::select(self.normal.cmpgt(Vec3A::ZERO), min, max);
        self.beyond(nearest)
    }
}

impl Visibility {
    /// True when no face other than `ignore` can stop a ray from `p` (receiving side facing
    /// the unit `n`) through any point of `polygon` in front of `p`; false when one may
    /// (or when no part of `polygon` lies in front).
    pub fn shaft_is_empty(&self, p: DVec3, n: DVec3, polygon: &ConvexPolygon, ignore: u32) -> bool {
        let mut front = [DVec3::ZERO; MAX_CLIPPED];
        let count = polygon.clip_above(p, n, &mut front);
        if count < 3 {
            return false;
        }
        front[..count].iter_mut().for_each(|x| *x = self.rotation * *x);
        let mut planes = [Plane { normal: Vec3A::ZERO, offset: 0.0 }; MAX_CLIPPED + 1];
        let apex = self.rotation * p;
        let filled = bounding_planes(apex, self.rotation * n, &front[..count], self.epsilon, &mut planes);
        let planes = &planes[..filled];
        let tree = self.shafts.get_or_init(|| shaft_tree(&self.triangles));
        let outside_box = |min: Vec3A, max: Vec3A| planes.iter().any(|s| s.beyond_box(min, max));
        let outside = |t: &Triangle| planes.iter().any(|s| s.beyond(t.v0) && s.beyond(t.v1) && s.beyond(t.v2));
        let (mut stack, mut top) = ([0u32; STACK], 1);
        while top > 0 {
            top -= 1;
            let node = &tree.nodes[stack[top] as usize];
            if outside_box(node.aabb.min, node.aabb.max) {
                continue;
            }
            if node.prim_count == 0 {
                if top + 2 > STACK {
                    return false; // deeper than the stack: taken as in the way
                }
                stack[top..top + 2].copy_from_slice(&[node.first_index, node.first_index + 1]);
                top += 2;
                continue;
            }
            let first = node.first_index as usize;
            for &k in &tree.primitive_indices[first..first + node.prim_count as usize] {
                let k = k as usize;
                if self.face_of[k] != ignore && !outside(&self.triangles[k]) {
                    return false;
                }
            }
        }
        true
    }
}

/// The planes of the shaft from `apex` (receiving normal `n`) through the convex polygon
/// `front` (wholly in front of the apex's plane) and on beyond it, each moved inwards by
/// `slack`: the apex's plane and one through the apex and each edge. Returns how many of
/// `planes` it filled.
fn bounding_planes(apex: DVec3, n: DVec3, front: &[DVec3], slack: f64, planes: &mut [Plane]) -> usize {
    planes[0] = Plane::new(-n, apex, slack);
    let mut count = 1;
    for outward in edge_sides(apex, front) {
        planes[count] = Plane::new(outward, apex, slack);
        count += 1;
    }
    count
}

/// What stands between a point and the pieces of an opening or of a face: whether the point
/// sees `x` (the ray from the point through `x` leaves the scene; or, for a face's point
/// (`between.rs`), the segment to it crosses no other face), and whether nothing at all
/// stands before a whole `piece` (so that no ray need be traced through it).
pub trait Sight {
    /// True when the point sees `x`.
    fn sees(&self, x: DVec3) -> bool;
    /// True when no face can stop a ray from the point through (or to) `piece`; false when
    /// one may.
    fn clear(&self, piece: &ConvexPolygon) -> bool;
    /// True when one opaque piece stops every ray from the point through `piece`; false
    /// when none is known to. Adds the rays it traced to `rays`.
    fn hidden(&self, piece: &ConvexPolygon, rays: &mut usize) -> bool;
}

/// A bare test `sees(x)`: no piece is known to be clear without its rays.
impl<F: Fn(DVec3) -> bool> Sight for F {
    fn sees(&self, x: DVec3) -> bool {
        self(x)
    }

    fn clear(&self, _: &ConvexPolygon) -> bool {
        false
    }

    fn hidden(&self, _: &ConvexPolygon, _: &mut usize) -> bool {
        false
    }
}

/// The scene's faces seen from `p` (receiving side facing the unit `n`, lying on the face
/// `ignore`): rays that leave the scene, and shafts. Its rays try the triangle that
/// blocked its last one first (`Visibility::visible_cached`): the rays from one point
/// through the pieces of an opening hidden behind a wall all stop on the same triangle;
/// and a piece is hidden when the occluder that hid the last one hides it too.
pub struct SightFrom<'a> {
    visibility: &'a Visibility,
    p: DVec3,
    n: DVec3,
    ignore: u32,
    last: Cell<Blocker>,
    occluder: Cell<Option<&'a ConvexPolygon>>,
}

impl<'a> SightFrom<'a> {
    /// What `visibility`'s faces let `p` see, its receiving side facing the unit `n`, lying
    /// on the face `ignore`.
    pub fn new(visibility: &'a Visibility, p: DVec3, n: DVec3, ignore: u32) -> SightFrom<'a> {
        SightFrom { visibility, p, n, ignore, last: Cell::new(NO_BLOCKER), occluder: Cell::new(None) }
    }
}

impl Sight for SightFrom<'_> {
    fn sees(&self, x: DVec3) -> bool {
        let mut last = self.last.get();
        let escapes = self.visibility.escapes_cached(self.p, x - self.p, self.ignore, &mut last);
        self.last.set(last);
        escapes
    }

    fn clear(&self, piece: &ConvexPolygon) -> bool {
        self.visibility.shaft_is_empty(self.p, self.n, piece, self.ignore)
    }

    /// The last occluder first; else the occluder of the face that stops the ray through
    /// the piece's centroid, if one does.
    fn hidden(&self, piece: &ConvexPolygon, rays: &mut usize) -> bool {
        let Some(occluders) = &self.visibility.occluders else {
            return false;
        };
        let margin = self.visibility.epsilon;
        if self.occluder.get().is_some_and(|o| hides(o, self.p, piece, margin)) {
            return true;
        }
        *rays += 1;
        if self.sees(piece.centroid()) {
            return false;
        }
        let face = self.last.get().0.map(|id| self.visibility.face_of[id]);
        let occluder = face.and_then(|f| occluders.of_face(f));
        self.occluder.set(occluder.or(self.occluder.get()));
        occluder.is_some_and(|o| hides(o, self.p, piece, margin))
    }
}
