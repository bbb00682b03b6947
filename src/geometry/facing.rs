//! Whether two patches face each other: the test that decides which pairs of patches
//! exchange light at all (`docs/design.md` §3), shared by the kernels' assembly and by the
//! estimates of their size.

use super::Patch;

/// True when some part of each patch lies strictly in front of the other.
pub fn facing(a: &Patch, b: &Patch) -> bool {
    let ahead = |p: &Patch, q: &Patch| {
        let eps = 1e-9 * (p.area + q.area).sqrt();
        q.polygon.vertices().iter().any(|v| (*v - p.centroid).dot(p.normal) > eps)
    };
    ahead(a, b) && ahead(b, a)
}
