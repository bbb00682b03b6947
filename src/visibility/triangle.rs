//! The triangle test of every traversal: Möller–Trumbore with a slack on the barycentric
//! coordinates, on triangles stored with their edges precomputed (the same `f32` edges the
//! test would compute, so the answers are those of the test on the plain vertices).

use glam::Vec3A;
use obvhs::{ray::Ray, triangle::Triangle};

/// Barycentric slack that closes the cracks between triangles sharing an edge.
pub const EDGE_SLACK: f32 = 1e-5;

/// A triangle as the test reads it: a vertex and the two edges from it.
#[derive(Debug, Clone, Copy)]
pub struct Tri {
    v0: Vec3A,
    e1: Vec3A,
    e2: Vec3A,
}

impl Tri {
    /// The test's form of `t`.
    pub fn of(t: &Triangle) -> Tri {
        Tri { v0: t.v0, e1: t.v1 - t.v0, e2: t.v2 - t.v0 }
    }

    /// The distance along `ray` at which it crosses the triangle within its `tmin`..`tmax`,
    /// or infinity.
    #[inline(always)]
    pub fn hit(&self, ray: &Ray) -> f32 {
        let (e1, e2) = (self.e1, self.e2);
        let p = ray.direction.cross(e2);
        let det = e1.dot(p);
        if det.abs() < 1e-20 {
            return f32::INFINITY;
        }
        let inv = 1.0 / det;
        let s = ray.origin - self.v0;
        let u = s.dot(p) * inv;
        let q = s.cross(e1);
        let v = ray.direction.dot(q) * inv;
        let t = e2.dot(q) * inv;
        let inside = u >= -EDGE_SLACK && v >= -EDGE_SLACK && u + v <= 1.0 + EDGE_SLACK;
        if inside && t > ray.tmin && t < ray.tmax { t } else { f32::INFINITY }
    }
}
