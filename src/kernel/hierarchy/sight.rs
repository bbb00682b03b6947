//! Visibility between two elements (`design.md` §3b, "Links": the factor times a visibility
//! fraction): the 4 × 4 segments of `occlusion::visible_fraction` (4 first, all 16 when
//! they disagree), classified as clear, partial or occluded. Blocked segments do not prove
//! that nothing passes between two large elements, so the oracle refines occluded links
//! like partial ones and drops them only once it accepts them.

use crate::geometry::Patch;
use crate::kernel::occlusion::{polygon_points, visible_fraction};
use crate::visibility::{Blocker, Visibility};

/// How much of one element sees the other.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Sight {
    /// Every tested segment is free.
    Clear,
    /// Some segments are blocked, some free: a shadow boundary crosses the pair.
    Partial,
    /// Every tested segment is blocked.
    Occluded,
    /// Not tested: a link of a cluster (its light is bounded by the oracle instead).
    Untested,
}

/// The visible fraction of the pair `(a, b)`, its class and the rays it took.
pub fn sight(visibility: &Visibility, a: &Patch, b: &Patch, blocker: &mut Blocker) -> (Sight, f64, usize) {
    let (pa, pb) = (polygon_points(&a.polygon), polygon_points(&b.polygon));
    let v = visible_fraction(visibility, a, &pa, b, &pb, blocker);
    let class = match v.fraction {
        f if f >= 1.0 => Sight::Clear,
        f if f > 0.0 => Sight::Partial,
        _ => Sight::Occluded,
    };
    (class, v.fraction, v.rays)
}
