//! Visibility fractions `V_ij` between two patches: the mean of the pupil function `Θ`
//! over segments joining stratified points of the two patches (`docs/design.md` §3).
//!
//! The same points serve both directions, so `V_ij = V_ji` and occlusion keeps the
//! kernel reciprocal. Four segments (point `k` to point `k` of the other patch) are tested
//! first; only when they disagree (a penumbra) are all `POINTS²` segments traced.

use crate::geometry::{ConvexPolygon, Patch};
use crate::visibility::{Blocker, Segment, Sight, Visibility};
use glam::DVec3;

/// Points per patch; a pair is tested with `POINTS²` segments.
pub const POINTS: usize = 4;

/// Four stratified interior points of a patch.
pub fn sample_points(p: &Patch) -> [DVec3; POINTS] {
    polygon_points(&p.polygon)
}

/// Four stratified interior points of a triangle or convex quad.
pub fn polygon_points(polygon: &ConvexPolygon) -> [DVec3; POINTS] {
    let v = polygon.vertices();
    if v.len() == 4 {
        let at = |s: f64, t: f64| v[0].lerp(v[1], s).lerp(v[3].lerp(v[2], s), t);
        [at(0.25, 0.25), at(0.75, 0.25), at(0.75, 0.75), at(0.25, 0.75)]
    } else {
        let c = (v[0] + v[1] + v[2]) / 3.0;
        [(4.0 * v[0] + v[1] + v[2]) / 6.0, (v[0] + 4.0 * v[1] + v[2]) / 6.0, (v[0] + v[1] + 4.0 * v[2]) / 6.0, c]
    }
}

/// Fraction of the `POINTS²` segments between `a` and `b` that no other face blocks.
pub fn visible_fraction(
    visibility: &Visibility,
    a: &Patch,
    pa: &[DVec3; POINTS],
    b: &Patch,
    pb: &[DVec3; POINTS],
    blocker: &mut Blocker,
) -> VisibleFraction {
    fraction_between(visibility, &pa.map(|x| (x, a.face)), &pb.map(|x| (x, b.face)), blocker)
}

/// Fraction of the `POINTS²` segments between the points `a` and `b`, each on the face it
/// names, that no other face blocks: point `k` to point `k` first, traced together, and only
/// when they disagree the other segments, row by row, traced together.
pub fn fraction_between(
    visibility: &Visibility,
    a: &[(DVec3, u32); POINTS],
    b: &[(DVec3, u32); POINTS],
    blocker: &mut Blocker,
) -> VisibleFraction {
    let segment = |(k, m): (usize, usize)| (a[k].0, b[m].0, [a[k].1, b[m].1]);
    let diagonal: [Segment; POINTS] = std::array::from_fn(|k| segment((k, k)));
    let first = visibility.visible_together(&diagonal, blocker).count_ones() as usize;
    if first == 0 || first == POINTS {
        return VisibleFraction { fraction: (first / POINTS) as f64, rays: POINTS };
    }
    let mut rest = [diagonal[0]; POINTS * POINTS - POINTS];
    let off_diagonal = (0..POINTS).flat_map(|k| (0..POINTS).map(move |m| (k, m))).filter(|(k, m)| k != m);
    rest.iter_mut().zip(off_diagonal).for_each(|(s, km)| *s = segment(km));
    let seen = first + visibility.visible_together(&rest, blocker).count_ones() as usize;
    VisibleFraction { fraction: seen as f64 / (POINTS * POINTS) as f64, rays: POINTS * POINTS }
}

/// A visibility fraction and the rays it took.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct VisibleFraction {
    /// The visible fraction, 0 to 1.
    pub fraction: f64,
    /// Rays cast.
    pub rays: usize,
}

/// What the test points of a piece of a patch see: how many of its [`POINTS`] stratified
/// points, and whether those and its corners (pulled in by 0.1 % towards its centroid) all
/// agree. A straight shadow edge across the piece always separates two corners, so a piece
/// that is not `uniform` is cut further by the callers (probes, luminaires).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PieceVisibility {
    /// Stratified points that see.
    pub seen: usize,
    /// True when the points and the corners all agree.
    pub uniform: bool,
    /// Rays cast.
    pub rays: usize,
}

/// Tests the points of `polygon` with `sees`.
pub fn piece_visibility(polygon: &ConvexPolygon, sees: impl Fn(DVec3) -> bool) -> PieceVisibility {
    let seen = polygon_points(polygon).iter().filter(|&&x| sees(x)).count();
    let centroid = polygon.centroid();
    let corners = polygon.vertices();
    let partial = seen > 0 && seen < POINTS;
    let uniform = !partial && corners.iter().all(|v| sees(v.lerp(centroid, 1e-3)) == (seen == POINTS));
    PieceVisibility { seen, uniform, rays: POINTS + if partial { 0 } else { corners.len() } }
}

/// Most levels of cutting a partly visible piece into quarters along a shadow edge.
pub const SHADOW_DEPTH: u32 = 6;

/// Cuts `piece` (already cut `depth` times) into quarters while its test points and corners
/// disagree about what `sight` sees (a shadow edge crosses it), down to [`SHADOW_DEPTH`]
/// levels and only while `worth` says the piece matters enough, and hands every final piece
/// that some of its points see to `visit` with the fraction of its points that see. A piece
/// that will not be cut (the deepest level, or not `worth` it) is tested with its points
/// alone; a piece `sight` knows to be clear is handed on whole and seen, without rays, as
/// they would all have seen. Returns the rays traced.
pub fn cut_along_shadows(
    piece: &ConvexPolygon,
    depth: u32,
    sight: &dyn Sight,
    worth: &dyn Fn(&ConvexPolygon) -> bool,
    visit: &mut dyn FnMut(&ConvexPolygon, f64),
) -> usize {
    if sight.clear(piece) {
        visit(piece, 1.0);
        return 0;
    }
    if depth >= SHADOW_DEPTH || !worth(piece) {
        let seen = polygon_points(piece).iter().filter(|&&x| sight.sees(x)).count();
        if seen > 0 {
            visit(piece, seen as f64 / POINTS as f64);
        }
        return POINTS;
    }
    let test = piece_visibility(piece, |x| sight.sees(x));
    if !test.uniform {
        return test.rays
            + piece.split().iter().map(|part| cut_along_shadows(part, depth + 1, sight, worth, visit)).sum::<usize>();
    }
    if test.seen > 0 {
        visit(piece, test.seen as f64 / POINTS as f64);
    }
    test.rays
}

/// Hands `piece` to `visit` seen whole when the one of its [`POINTS`] stratified points
/// that `pick` names (modulo [`POINTS`]) is seen by `sight`, else not at all: with `pick`
/// uniform, an unbiased estimate of the fraction of its points that see, for one ray.
/// Returns the rays traced (one).
pub fn sample_one(
    piece: &ConvexPolygon,
    sight: &dyn Sight,
    pick: u64,
    visit: &mut dyn FnMut(&ConvexPolygon, f64),
) -> usize {
    if sight.sees(polygon_points(piece)[(pick % POINTS as u64) as usize]) {
        visit(piece, 1.0);
    }
    1
}
