//! Form factors between patches far apart for their size, by point-to-point cubature
//! (`docs/design.md` §3b, equation (3b.6)): where a patch lies wholly in front of a point's
//! plane, faces the point, and is small against its distance, the kernel
//! `cosθ cosθ' / (π r²)` varies little over it, and the degree-2 three-point rule on each
//! fan triangle replaces Lambert's contour integral (3.9) (an arc tangent per edge, after
//! clipping). Anywhere else the exact integral is taken, so callers may ask for any pair.

use super::contour::point_to_patch;
use super::form_factor::three_point;
use crate::geometry::Patch;
use glam::DVec3;
use std::f64::consts::PI;

/// A patch counts as far from a point when its diameter is at most this share of its
/// distance from the point (less its radius): the cubature's largest relative error is
/// then 5e-4 (`tests/transfer/far_field.rs`).
pub const FAR: f64 = 0.25;

/// The form factor from the differential area at `x` (unit normal `n`) to `t`: by the
/// cubature when `t` is far from `x`, else by the contour integral.
pub fn point_factor(x: DVec3, n: DVec3, t: &Patch) -> f64 {
    if is_far(x, n, t) { cubature(x, n, t) } else { point_to_patch(x, n, t) }
}

/// `∫_{P_s} F_{dA→P_t} dA` by the three-point rule over `s` with the cubature at each
/// point, when `s` is far from `t`'s centroid and `t` from every point; none otherwise.
pub fn far_pair_integral(s: &Patch, t: &Patch) -> Option<f64> {
    let mut far = is_far(t.centroid, t.normal, s);
    let mut sum = 0.0;
    for tri in s.polygon.triangles() {
        sum += three_point(&tri, &mut |x, w| {
            far &= is_far(x, s.normal, t);
            w * cubature(x, s.normal, t)
        });
    }
    far.then_some(sum)
}

/// True when `t` lies wholly in front of `x`'s plane, `x` in front of `t`'s, and `t` is
/// small against its distance from `x` ([`FAR`]).
pub fn is_far(x: DVec3, n: DVec3, t: &Patch) -> bool {
    let vertices = t.polygon.vertices();
    let radius2 = vertices.iter().map(|v| v.distance_squared(t.centroid)).fold(0.0, f64::max);
    // 2r ≤ FAR (d − r), squared: r (2 + FAR) ≤ FAR d
    radius2 * (2.0 + FAR) * (2.0 + FAR) <= FAR * FAR * x.distance_squared(t.centroid)
        && (x - t.centroid).dot(t.normal) > 0.0
        && vertices.iter().all(|v| (*v - x).dot(n) > 0.0)
}

/// `Σ_k w_k cosθ_k cosθ'_k / (π r_k²)` over the three-point rule's points `y_k` on each fan
/// triangle of `t`, from `x` with normal `n`.
fn cubature(x: DVec3, n: DVec3, t: &Patch) -> f64 {
    let mut sum = 0.0;
    for [a, b, c] in t.polygon.triangles() {
        let w = 0.5 * (b - a).cross(c - a).length();
        let mut part = 0.0;
        for y in [a * P + (b + c) * Q, b * P + (a + c) * Q, c * P + (a + b) * Q] {
            let r = y - x;
            let r2 = r.length_squared();
            part += r.dot(n) * -r.dot(t.normal) / (r2 * r2);
        }
        sum += w * part;
    }
    sum / (3.0 * PI)
}

/// The three-point rule's barycentric coordinates, `(P, Q, Q)` and permutations.
const P: f64 = 2.0 / 3.0;
const Q: f64 = 1.0 / 6.0;
