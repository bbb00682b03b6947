//! Patch-to-patch form factors without occlusion (`docs/design.md` §3), whole or split by
//! direction cells (`F_ij^{d,m}`).
//!
//! `A_s F_st = ∫_{A_s} F_{dA(x)→P_t} dA(x)`: the inner integral is exact (Lambert's
//! contour integral, [`point_to_polygon`]); the outer one is a quadrature over the fan
//! triangles of `P_s`, with a degree-2 three-point rule on each. A triangle is split into
//! four while its diameter exceeds `η` times its distance to `P_t` (up to a depth limit),
//! so the quadrature is graded towards shared edges and close neighbours, where the
//! integrand varies fastest. The un-refined *base rule* is returned as well: summed over
//! all targets with the same points, it gives the patch's closure exactly (up to
//! visibility), which the assembly uses to balance the kernel.
//!
//! Split by cells, the target seen from each base-rule point `x` is cut into triangles
//! until each looks smaller than `κ` times a cell's angular size from `x` (at most 4
//! levels); each piece's exact contour integral goes to the cell `d` of its direction at
//! `s` and the cell `m` of the opposite direction at `t`. The pieces partition the
//! target; scaled to the adaptive total, the cells sum to the whole form factor to
//! round-off, and only the split between cells rests on the coarser base rule.

use super::contour::{point_to_patch, point_to_polygon};
use crate::directions::DirectionSet;
use crate::geometry::{ConvexPolygon, Frame, Patch};
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

/// How targets are split by direction cells.
#[derive(Debug, Clone, Copy)]
pub struct Binning<'a> {
    /// The direction cells pieces are binned into.
    pub directions: &'a DirectionSet,
    /// A target piece is split while its angular size exceeds `kappa` cell sizes.
    pub kappa: f64,
    /// Angular size of the smallest cell, rad (`√ω_min`).
    pub cell_size: f64,
}

impl<'a> Binning<'a> {
    /// The binning on `directions` with `kappa = 0.5`.
    pub fn new(directions: &'a DirectionSet) -> Self {
        let smallest = directions.cells().iter().map(|c| c.solid_angle).fold(f64::INFINITY, f64::min);
        Binning { directions, kappa: 0.5, cell_size: smallest.sqrt() }
    }
}

/// Most levels of splitting a target into pieces for binning.
const MAX_PIECE_DEPTH: u32 = 4;

/// `A_s F_st` by the adaptive rule, and by the base rule (no refinement), m².
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PairIntegral {
    /// By the adaptive rule, m².
    pub adaptive: f64,
    /// By the base rule, m².
    pub base: f64,
}

/// `∫_{P_s} F_{dA→P_t} dA` by adaptive and by base quadrature.
pub fn pair_integral(s: &Patch, t: &Patch, q: &Quadrature) -> PairIntegral {
    let mut adaptive = 0.0;
    let mut base = 0.0;
    for tri in s.polygon.triangles() {
        let b = three_point(&tri, &mut |x, w| w * point_to_patch(x, s.normal, t));
        base += b;
        adaptive += refine(&tri, t, q, 0, Some(b), &mut |x, w| w * point_to_patch(x, s.normal, t));
    }
    PairIntegral { adaptive, base }
}

/// Like [`pair_integral`], and also pushes `(d, m, A_s F_st^{d,m})` pieces onto `bins`
/// (unmerged: one cell pair may appear several times). The pieces carry the adaptive
/// total, distributed over cell pairs as the base rule's points see the target.
pub fn binned_pair_integral(
    s: &Patch,
    t: &Patch,
    q: &Quadrature,
    binning: &Binning,
    bins: &mut Vec<(u16, u16, f64)>,
) -> PairIntegral {
    let whole = pair_integral(s, t, q);
    if whole.adaptive <= 0.0 {
        return whole;
    }
    let start = bins.len();
    let frame = s.frame();
    let mut seen = 0.0;
    for tri in s.polygon.triangles() {
        seen += three_point(&tri, &mut |x, w| {
            t.polygon.triangles().map(|piece| split_piece(x, &frame, t, &piece, binning, w, 0, bins)).sum()
        });
    }
    if seen > 0.0 {
        let scale = whole.adaptive / seen;
        bins[start..].iter_mut().for_each(|b| b.2 *= scale);
    } else {
        // only refined points see the target: give it the cells of the centroid directions
        let d = binning.directions.lookup(frame.local((t.centroid - s.centroid).normalize()));
        let m = binning.directions.lookup(t.frame().local((s.centroid - t.centroid).normalize()));
        bins.push((d as u16, m as u16, whole.adaptive));
    }
    whole
}

/// The form factor `F_st` (fraction of `s`'s hemisphere covered by `t`), adaptive rule.
pub fn form_factor(s: &Patch, t: &Patch, q: &Quadrature) -> f64 {
    pair_integral(s, t, q).adaptive / s.area
}

/// Form factor from the point `x` (frame `at`, its normal facing `t`) to patch `t`,
/// split by cells: pushes `(d at x, m at t, F piece)` onto `bins` and returns the total.
/// With one cell, the whole patch's factor in one contour integral.
pub fn binned_point(x: DVec3, at: &Frame, t: &Patch, binning: &Binning, bins: &mut Vec<(u16, u16, f64)>) -> f64 {
    if binning.directions.len() == 1 {
        let f = point_to_patch(x, at.normal, t);
        if f > 0.0 {
            bins.push((0, 0, f));
        }
        return f.max(0.0);
    }
    t.polygon.triangles().map(|piece| split_piece(x, at, t, &piece, binning, 1.0, 0, bins)).sum()
}

/// Weighted form factor from `x` to a triangle piece of `t`, binned; returns its total.
#[allow(clippy::too_many_arguments)]
fn split_piece(
    x: DVec3,
    s: &Frame,
    t: &Patch,
    piece: &[DVec3; 3],
    binning: &Binning,
    weight: f64,
    depth: u32,
    bins: &mut Vec<(u16, u16, f64)>,
) -> f64 {
    let c = (piece[0] + piece[1] + piece[2]) / 3.0;
    let diameter = piece[0].distance(piece[1]).max(piece[1].distance(piece[2])).max(piece[2].distance(piece[0]));
    if depth < MAX_PIECE_DEPTH && diameter > binning.kappa * binning.cell_size * c.distance(x) {
        let [a, b, d] = *piece;
        let (ab, bd, da) = (0.5 * (a + b), 0.5 * (b + d), 0.5 * (d + a));
        return [[a, ab, da], [ab, b, bd], [da, bd, d], [ab, bd, da]]
            .iter()
            .map(|p| split_piece(x, s, t, p, binning, weight, depth + 1, bins))
            .sum();
    }
    let f = point_to_polygon(x, s.normal, &ConvexPolygon::triangle(piece[0], piece[1], piece[2]));
    if f <= 0.0 {
        return 0.0;
    }
    let d = binning.directions.lookup(s.local((c - x).normalize()));
    let m = binning.directions.lookup(t.frame().local((x - c).normalize()));
    bins.push((d as u16, m as u16, weight * f));
    weight * f
}

fn refine(
    tri: &[DVec3; 3],
    t: &Patch,
    q: &Quadrature,
    depth: u32,
    known: Option<f64>,
    f: &mut dyn FnMut(DVec3, f64) -> f64,
) -> f64 {
    let centroid = (tri[0] + tri[1] + tri[2]) / 3.0;
    let diameter = tri[0].distance(tri[1]).max(tri[1].distance(tri[2])).max(tri[2].distance(tri[0]));
    if depth >= q.max_depth || diameter <= q.eta * t.polygon.distance_to(centroid) {
        return known.unwrap_or_else(|| three_point(tri, f));
    }
    let [a, b, c] = *tri;
    let (ab, bc, ca) = (0.5 * (a + b), 0.5 * (b + c), 0.5 * (c + a));
    [[a, ab, ca], [ab, b, bc], [ca, bc, c], [ab, bc, ca]]
        .iter()
        .map(|child| refine(child, t, q, depth + 1, None, f))
        .sum()
}

/// Degree-2 rule: barycentric points (2/3, 1/6, 1/6) and permutations, equal weights;
/// `f(x, w)` returns the weighted integrand at `x`.
pub(super) fn three_point(tri: &[DVec3; 3], f: &mut dyn FnMut(DVec3, f64) -> f64) -> f64 {
    let [a, b, c] = *tri;
    let w = 0.5 * (b - a).cross(c - a).length() / 3.0;
    let (p, q) = (2.0 / 3.0, 1.0 / 6.0);
    f(a * p + b * q + c * q, w) + f(a * q + b * p + c * q, w) + f(a * q + b * q + c * p, w)
}
