//! Visibility between two elements (`docs/design.md` §3b, "Links": the factor times a visibility
//! fraction): the 4 × 4 segments of `occlusion::visible_fraction` (4 first, all 16 when
//! they disagree), classified as clear, partial or occluded. Blocked segments do not prove
//! that nothing passes between two large elements, so the oracle refines occluded links
//! like partial ones and drops them only once it accepts them. A cluster is represented by
//! the centroids of four of its elements, one from each quarter of its median splits; a
//! pair whose stand-ins see nothing of each other is always refined (`refine.rs`).

use super::tree::Tree;
use crate::geometry::Patch;
use crate::transfer::occlusion::{POINTS, fraction_between, polygon_points, visible_fraction};
use crate::visibility::{Blocker, Visibility};
use glam::DVec3;

/// How much of one element sees the other.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Sight {
    /// Every tested segment is free.
    Clear,
    /// Some segments are blocked, some free: a shadow boundary crosses the pair.
    Partial,
    /// Every tested segment is blocked.
    Occluded,
}

impl Sight {
    /// The class of a visible fraction (all, some or none of the tested segments free): a
    /// link keeps only its fraction.
    pub fn of(fraction: f64) -> Sight {
        match fraction {
            f if f >= 1.0 => Sight::Clear,
            f if f > 0.0 => Sight::Partial,
            _ => Sight::Occluded,
        }
    }
}

/// The visible fraction of the pair `(a, b)`, its class and the rays it took.
pub fn sight(visibility: &Visibility, a: &Patch, b: &Patch, blocker: &mut Blocker) -> (Sight, f64, usize) {
    let (pa, pb) = (polygon_points(&a.polygon), polygon_points(&b.polygon));
    let v = visible_fraction(visibility, a, &pa, b, &pb, blocker);
    (Sight::of(v.fraction), v.fraction, v.rays)
}

/// Four points standing for node `id` as seen from `towards`, each with the face it lies
/// on: an element's stratified points; for a cluster, centroids of elements that face
/// `towards`, taken in turn from the quarters of its median splits (up to
/// [`STAND_IN_SEARCH`] elements of each are searched; the first elements when none faces):
/// the cluster's orientation is already in its factor, only what blocks the way counts.
pub fn stand_ins(tree: &Tree, id: u32, towards: DVec3) -> [(DVec3, u32); POINTS] {
    if let Some(patch) = tree.node(id).patch() {
        return polygon_points(&patch.polygon).map(|x| (x, patch.face));
    }
    let quarters: Vec<Vec<&Patch>> = tree
        .children(id)
        .iter()
        .flat_map(|&c| halves(tree, c))
        .map(|q| Elements { tree, stack: vec![q] }.take(STAND_IN_SEARCH).collect())
        .collect();
    let facing: Vec<Vec<&Patch>> = quarters
        .iter()
        .map(|q| q.iter().copied().filter(|p| (towards - p.centroid).dot(p.normal) > 0.0).collect())
        .collect();
    let pool = if facing.iter().any(|q| !q.is_empty()) { &facing } else { &quarters };
    let chosen = in_turn(pool);
    std::array::from_fn(|k| {
        chosen.get(k % chosen.len().max(1)).map_or((tree.node(id).centre(), u32::MAX), |p| (p.centroid, p.face))
    })
}

/// Up to [`POINTS`] elements, one from each non-empty list in turn.
fn in_turn<'a>(lists: &[Vec<&'a Patch>]) -> Vec<&'a Patch> {
    let mut out = Vec::with_capacity(POINTS);
    for k in 0..POINTS {
        out.extend(lists.iter().filter_map(|l| l.get(k)).take(POINTS - out.len()));
    }
    out
}

/// How many elements of a quarter are searched for one facing the other end.
pub const STAND_IN_SEARCH: usize = 16;

/// The elements (top-level ones: a cluster's members) under a node, depth first.
struct Elements<'a> {
    tree: &'a Tree,
    stack: Vec<u32>,
}

impl<'a> Iterator for Elements<'a> {
    type Item = &'a Patch;

    fn next(&mut self) -> Option<&'a Patch> {
        while let Some(id) = self.stack.pop() {
            match self.tree.node(id).patch() {
                Some(patch) => return Some(patch),
                None => self.stack.extend(self.tree.children(id).iter().rev()),
            }
        }
        None
    }
}

/// The children of a cluster, or the element itself.
fn halves(tree: &Tree, id: u32) -> Vec<u32> {
    match tree.node(id).patch() {
        Some(_) => vec![id],
        None => tree.children(id).to_vec(),
    }
}

/// The visible fraction between the stand-ins of two nodes (4 segments first, all 16 when
/// they disagree), its class and the rays it took.
pub fn stand_in_sight(
    visibility: &Visibility,
    a: &[(DVec3, u32); POINTS],
    b: &[(DVec3, u32); POINTS],
    blocker: &mut Blocker,
) -> (Sight, f64, usize) {
    let v = fraction_between(visibility, a, b, blocker);
    (Sight::of(v.fraction), v.fraction, v.rays)
}
