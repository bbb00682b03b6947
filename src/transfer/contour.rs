//! Lambert's contour integral: the exact form factor from a point to a polygon.
//!
//! `F_{dA→P} = (1/2π) Σ_i γ_i n·(R_i × R_{i+1})/|R_i × R_{i+1}|` with `R_i` the unit
//! vectors to the vertices and `γ_i` the angle between consecutive ones
//! (`docs/references.md`, configuration factors item 6). The polygon is first clipped to
//! the half-space in front of the point, so patches partly below the point's horizon are
//! handled exactly. This is the near-field-exact building block of `docs/design.md` §3,
//! equation (3.9).

use crate::geometry::{ConvexPolygon, MAX_CLIPPED, Patch, angle};
use glam::DVec3;
use std::f64::consts::PI;

/// Form factor from the differential area at `x` with unit normal `n` to `polygon`,
/// seen from its front side; 0 when `x` is behind the polygon's plane.
pub fn point_to_polygon(x: DVec3, n: DVec3, polygon: &ConvexPolygon) -> f64 {
    facing_polygon(x, n, polygon, polygon.normal())
}

/// [`point_to_polygon`] to a patch, with the normal it already holds (the hot loops call
/// it millions of times for the same patch).
pub fn point_to_patch(x: DVec3, n: DVec3, patch: &Patch) -> f64 {
    facing_polygon(x, n, &patch.polygon, patch.normal)
}

/// The factor to `polygon`, whose front faces along `front`.
fn facing_polygon(x: DVec3, n: DVec3, polygon: &ConvexPolygon, front: DVec3) -> f64 {
    let facing = (x - polygon.vertices()[0]).dot(front);
    if facing <= 0.0 {
        return 0.0;
    }
    let mut clipped = [DVec3::ZERO; MAX_CLIPPED];
    let count = polygon.clip_above(x, n, &mut clipped);
    projected_solid_angle(x, n, &clipped[..count]) / PI
}

/// `∫ cosθ dω` over the polygon (vertices counter-clockwise seen from `x`'s side
/// opposite to the polygon's front, i.e. as the polygon is oriented), all above `x`'s plane.
pub fn projected_solid_angle(x: DVec3, n: DVec3, vertices: &[DVec3]) -> f64 {
    if vertices.len() < 3 {
        return 0.0;
    }
    let mut sum = 0.0;
    let mut previous = (vertices[vertices.len() - 1] - x).normalize();
    for v in vertices {
        let current = (*v - x).normalize();
        let c = previous.cross(current);
        let s = c.length();
        if s > 1e-300 {
            let gamma = angle(s, previous.dot(current));
            sum += gamma * n.dot(c) / s;
        }
        previous = current;
    }
    // The polygon faces x, so its vertices run clockwise seen from x: the sum is negative.
    -0.5 * sum
}
