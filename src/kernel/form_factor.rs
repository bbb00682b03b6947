//! Patch-to-patch form factors `F_ij` without occlusion (`design.md` §3).
//!
//! `A_s F_st = ∫_{A_s} F_{dA(x)→P_t} dA(x)`: the inner integral is exact (Lambert's
//! contour integral, [`point_to_polygon`]); the outer one is a quadrature over the fan
//! triangles of `P_s`, with a degree-2 three-point rule on each. A triangle is split into
//! four while its diameter exceeds `η` times its distance to `P_t` (up to a depth limit),
//! so the quadrature is graded towards shared edges and close neighbours, where the
//! integrand varies fastest. The un-refined *base rule* is returned as well: summed over
//! all targets with the same points, it gives the patch's closure exactly (up to
//! visibility), which the assembly uses to balance the kernel.

use super::contour::point_to_polygon;
use crate::geometry::Patch;
use glam::DVec3;

/// Accuracy controls of the outer quadrature.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Quadrature {
    /// A triangle is refined while `diameter > eta · distance to the target`.
    pub eta: f64,
    /// Most levels of four-way refinement.
    pub max_depth: u32,
}

impl Default for Quadrature {
    fn default() -> Self {
        Quadrature { eta: 0.25, max_depth: 7 }
    }
}

/// `A_s F_st` by the adaptive rule, and by the base rule (no refinement), m².
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PairIntegral {
    pub adaptive: f64,
    pub base: f64,
}

/// `∫_{P_s} F_{dA→P_t} dA` by adaptive and by base quadrature.
pub fn pair_integral(s: &Patch, t: &Patch, q: &Quadrature) -> PairIntegral {
    let mut adaptive = 0.0;
    let mut base = 0.0;
    for tri in s.polygon.triangles() {
        let b = three_point(&tri, s.normal, t);
        base += b;
        adaptive += refine(&tri, s.normal, t, q, 0, Some(b));
    }
    PairIntegral { adaptive, base }
}

/// The form factor `F_st` (fraction of `s`'s hemisphere covered by `t`), adaptive rule.
pub fn form_factor(s: &Patch, t: &Patch, q: &Quadrature) -> f64 {
    pair_integral(s, t, q).adaptive / s.area
}

fn refine(tri: &[DVec3; 3], n: DVec3, t: &Patch, q: &Quadrature, depth: u32, known: Option<f64>) -> f64 {
    let centroid = (tri[0] + tri[1] + tri[2]) / 3.0;
    let diameter = tri[0].distance(tri[1]).max(tri[1].distance(tri[2])).max(tri[2].distance(tri[0]));
    if depth >= q.max_depth || diameter <= q.eta * t.polygon.distance_to(centroid) {
        return known.unwrap_or_else(|| three_point(tri, n, t));
    }
    let [a, b, c] = *tri;
    let (ab, bc, ca) = (0.5 * (a + b), 0.5 * (b + c), 0.5 * (c + a));
    [[a, ab, ca], [ab, b, bc], [ca, bc, c], [ab, bc, ca]]
        .iter()
        .map(|child| refine(child, n, t, q, depth + 1, None))
        .sum()
}

/// Degree-2 rule: barycentric points (2/3, 1/6, 1/6) and permutations, equal weights.
fn three_point(tri: &[DVec3; 3], n: DVec3, t: &Patch) -> f64 {
    let [a, b, c] = *tri;
    let area = 0.5 * (b - a).cross(c - a).length();
    let f = |x: DVec3| point_to_polygon(x, n, &t.polygon);
    let (p, q) = (2.0 / 3.0, 1.0 / 6.0);
    area / 3.0 * (f(a * p + b * q + c * q) + f(a * q + b * p + c * q) + f(a * q + b * q + c * p))
}
