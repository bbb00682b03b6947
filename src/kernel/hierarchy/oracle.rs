//! The refinement oracle (`docs/design.md` §3b, "Oracle"; Hanrahan, Salzman & Aupperle 1991):
//! a link is refined while `ρ_p · ΔF_pq · L_q > ε`, brightness-weighted (`L_q` times the
//! receiver's gain of (3b.3a) after the first pass, `brightness.rs`). `ΔF` bounds how
//! much the factor varies over the two nodes: the spread of the exact point-to-polygon
//! factors at sample points of each end (centroid, the four stratified occlusion points and
//! the corners pulled 1 % towards the centroid; the source's scaled by `A_q/A_p`), the
//! largest of them where visibility is partial, and for a link of a cluster the
//! conservative `A_q/(π d²)` with `d` the distance between the bounding boxes (infinite
//! when they touch). The larger node is split (the receiver when equal), never an element
//! whose longest edge is already the smallest element size (unless the slots' splits before
//! the linking gave it children, `slots.rs`: those it may refine into).
//!
//! Before any of that, an element that straddles a contact (partly inside a solid: its
//! exposed area strictly between 0 and its area, `docs/design.md` §3 "Contacts") is split
//! whatever the oracle says, down to the smallest size. Its four sample points stand for
//! its exposed part only on average: when all four lie inside the solid, every link from
//! them is occluded and would be dropped, and the exposed part would receive (and send)
//! nothing; when some do, the factors are the whole element's times a visible fraction.

use super::node::{Kind, Node};
use super::tree::Tree;
use crate::geometry::Patch;
use crate::transfer::far_field::point_factor;
use crate::transfer::occlusion::polygon_points;
use std::f64::consts::PI;

/// The refinement rule.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Oracle {
    /// Error allowed per link, cd/m².
    pub epsilon: f64,
    /// The finest patches' size (longest edge), m: no split below it.
    pub patch_size: f64,
}

/// The factor's variation over a pair of elements, from point factors at sample points.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Variation {
    /// `ΔF`: the largest spread at either end.
    pub spread: f64,
    /// The largest point factor at either end.
    pub largest: f64,
}

/// Point factors from the sample points of each element to the other.
pub fn variation(p: &Patch, q: &Patch) -> Variation {
    let (lo_p, hi_p) = extremes(p, q, 1.0);
    let (lo_q, hi_q) = extremes(q, p, q.area / p.area);
    Variation { spread: (hi_p - lo_p).max(hi_q - lo_q), largest: hi_p.max(hi_q) }
}

/// Smallest and largest `scale · F_{dA(x)→to}` over the sample points `x` of `from`.
fn extremes(from: &Patch, to: &Patch, scale: f64) -> (f64, f64) {
    sample_points(from).fold((f64::INFINITY, 0.0f64), |(lo, hi), x| {
        let f = scale * point_factor(x, from.normal, to);
        (lo.min(f), hi.max(f))
    })
}

/// The points where an element's variation is sampled: its four stratified points, its
/// corners pulled [`CORNER_INSET`] towards the centroid, and the centroid.
pub fn sample_points(patch: &Patch) -> impl Iterator<Item = glam::DVec3> + '_ {
    let corners = patch.polygon.vertices().iter().map(|v| v.lerp(patch.centroid, CORNER_INSET));
    polygon_points(&patch.polygon).into_iter().chain(corners).chain([patch.centroid])
}

/// How far the corner samples are pulled towards the centroid (off shared edges, where the
/// point factor of a neighbour drops to 0).
pub(super) const CORNER_INSET: f64 = 0.01;

/// `A_q/(π d²)`, at most 1, for a link with a cluster at one end; infinite when the
/// bounding boxes touch.
pub fn cluster_bound(p: &Node, q: &Node) -> f64 {
    let d = p.box_distance(q);
    if d <= 0.0 { f64::INFINITY } else { (q.area / (PI * d * d)).min(1.0) }
}

impl Oracle {
    /// `ρ_p · bound · L_q`, cd/m² (infinite for an infinite bound, even in the dark).
    pub fn error(&self, albedo: f64, bound: f64, brightness: f64) -> f64 {
        if bound.is_finite() { albedo * bound * brightness } else { f64::INFINITY }
    }

    /// True when a link with the estimated `error` must be refined (above `epsilon`).
    pub fn refines(&self, error: f64) -> bool {
        error > self.epsilon
    }

    /// The end of `(p, q)` to split first because it straddles a contact: an element partly
    /// inside a solid that can still be split.
    pub fn at_contact(&self, tree: &Tree, p: u32, q: u32) -> Option<u32> {
        [p, q].into_iter().find(|&n| tree.node(n).straddles_contact() && tree.can_split(n, self.patch_size))
    }

    /// The node to split to refine the link `(p, q)`: the cluster of an element–cluster
    /// pair (the bound does not depend on the receiving element's size), else the larger
    /// node (area for two elements, bounding-box diagonal otherwise), the receiver when
    /// equal; the other one when that cannot split; `None` when neither can.
    pub fn choose(&self, tree: &Tree, p: u32, q: u32) -> Option<u32> {
        let (a, b) = (tree.node(p), tree.node(q));
        let order = match (&a.kind, &b.kind) {
            (Kind::Element { .. }, Kind::Cluster) => [q, q],
            (Kind::Element { .. }, Kind::Element { .. }) => larger_first(p, q, a.area, b.area),
            _ => larger_first(p, q, a.diagonal(), b.diagonal()),
        };
        order.into_iter().find(|&n| tree.can_split(n, self.patch_size))
    }
}

/// `[p, q]` with the larger of the two sizes first (`p` when equal).
pub(super) fn larger_first(p: u32, q: u32, size_p: f64, size_q: f64) -> [u32; 2] {
    if size_q > size_p * (1.0 + 1e-9) { [q, p] } else { [p, q] }
}

/// The element of the pair `(p, q)` that grading splits toward the other down to `finest`
/// (m), the larger of those that `may` be split first, with whether it is a leaf of the
/// smallest size `patch_size` (m), which is split below it only if the pair sees something
/// of each other; `None` when neither can split down to `finest`.
pub(super) fn split_toward(
    tree: &Tree,
    (p, q): (u32, u32),
    finest: f64,
    patch_size: f64,
    may: impl Fn(u32) -> bool,
) -> Option<(u32, bool)> {
    let order = larger_first(p, q, tree.node(p).area, tree.node(q).area);
    let n = order.into_iter().find(|&n| may(n) && tree.can_split(n, finest))?;
    Some((n, tree.node(n).is_leaf() && !tree.can_split(n, patch_size)))
}
