//! `shape = "polygon"`: the rules a polygon's `vertices` must satisfy to be meshed into
//! the area it encloses: at least three, no two neighbours coinciding, not all on one
//! line, a non-zero area, planar, and simple (no edge crossing or touching another, no
//! fold back), since ear clipping of a bow tie, a pentagram or a pinched polygon gives
//! triangles of the wrong area.

use super::check::{REL_TOL, ZERO_AREA};
use glam::{DVec2, DVec3};

/// Most vertices of one polygon (the simplicity test compares every pair of edges); more
/// belong in an OBJ `mesh`.
const MAX_VERTICES: usize = 10_000;

/// Checks that `v` is a usable planar polygon; the error says what is wrong.
pub(super) fn polygon_defect(v: &[DVec3]) -> Result<(), String> {
    if v.len() < 3 {
        return Err(format!("a polygon needs at least 3 vertices, got {}", v.len()));
    }
    let size = bounding_diagonal(v);
    let next = |i: usize| v[(i + 1) % v.len()];
    if let Some(i) = (0..v.len()).find(|&i| (next(i) - v[i]).length() <= REL_TOL * size) {
        let j = (i + 1) % v.len();
        return Err(format!("vertices #{} and #{} coincide", i + 1, j + 1));
    }
    let far = v.iter().map(|&p| p - v[0]).max_by(|a, b| a.length().total_cmp(&b.length()));
    let axis = far.unwrap_or(DVec3::X).normalize_or_zero();
    if v.iter().all(|&p| (p - v[0]).cross(axis).length() <= REL_TOL * size) {
        return Err("all vertices lie on one line".to_string());
    }
    let newell: DVec3 = (0..v.len()).map(|i| v[i].cross(next(i))).sum();
    if newell.length() / 2.0 <= ZERO_AREA * size * size {
        return Err("the polygon has zero area".to_string());
    }
    let normal = newell.normalize();
    let centre = v.iter().sum::<DVec3>() / v.len() as f64;
    let off = |p: &DVec3| (*p - centre).dot(normal).abs();
    if let Some(i) = v.iter().position(|p| off(p) > REL_TOL * size) {
        return Err(format!("not planar: vertex #{} is {:.3e} m off the plane", i + 1, off(&v[i])));
    }
    simple(v, normal, size)
}

/// The diagonal of the axis-aligned bounding box of `v`.
fn bounding_diagonal(v: &[DVec3]) -> f64 {
    let min = v.iter().fold(DVec3::INFINITY, |m, &p| m.min(p));
    let max = v.iter().fold(DVec3::NEG_INFINITY, |m, &p| m.max(p));
    (max - min).length()
}

/// No edge crosses or touches another except its two neighbours at their shared vertex,
/// and no vertex folds its two edges back onto each other.
fn simple(v: &[DVec3], normal: DVec3, size: f64) -> Result<(), String> {
    let n = v.len();
    if n > MAX_VERTICES {
        return Err(format!("a polygon may have at most {MAX_VERTICES} vertices, got {n}; use shape = \"mesh\""));
    }
    let (e1, e2) = normal.any_orthonormal_pair();
    let origin = v[0];
    let p: Vec<DVec2> = v.iter().map(|&q| DVec2::new((q - origin).dot(e1), (q - origin).dot(e2))).collect();
    // Twice an area below this is round-off (a point within ~1e-6 of the size of a line).
    let eps = REL_TOL * size * size;
    let turn = |o: DVec2, a: DVec2, b: DVec2| (a - o).perp_dot(b - o);
    let on = |q: DVec2, a: DVec2, b: DVec2| {
        turn(a, b, q).abs() <= eps && (q - a).dot(b - a) >= -eps && (q - b).dot(a - b) >= -eps
    };
    for i in 0..n {
        let (a, b, c) = (p[i], p[(i + 1) % n], p[(i + 2) % n]);
        if turn(b, a, c).abs() <= eps && (a - b).dot(c - b) > 0.0 {
            return Err(format!(
                "not a simple polygon: it folds back on itself at vertex #{} (the edges to and from it overlap)",
                (i + 1) % n + 1
            ));
        }
    }
    let edge = |i: usize| (p[i], p[(i + 1) % n]);
    for i in 0..n {
        for j in i + 2..n {
            if i == 0 && j == n - 1 {
                continue;
            }
            let ((a, b), (c, d)) = (edge(i), edge(j));
            let (d1, d2, d3, d4) = (turn(a, b, c), turn(a, b, d), turn(c, d, a), turn(c, d, b));
            let apart = |x: f64, y: f64| (x > eps && y < -eps) || (x < -eps && y > eps);
            let how = if apart(d1, d2) && apart(d3, d4) {
                "cross"
            } else if on(c, a, b) || on(d, a, b) || on(a, c, d) || on(b, c, d) {
                "touch"
            } else {
                continue;
            };
            return Err(format!(
                "not a simple polygon: edge #{} (vertices #{} → #{}) and edge #{} (vertices #{} → #{}) {how}; \
                 split it into simple polygons",
                i + 1,
                i + 1,
                (i + 1) % n + 1,
                j + 1,
                j + 1,
                (j + 1) % n + 1
            ));
        }
    }
    Ok(())
}
