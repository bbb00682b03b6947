//! Visibility between two elements (`docs/design.md` §3b, "Links": the factor times a visibility
//! fraction): the 4 × 4 segments of `occlusion::visible_fraction` (4 first, all 16 when
//! they disagree), classified as clear, partial or occluded. Blocked segments do not prove
//! that nothing passes between two large elements, so the oracle refines occluded links
//! like partial ones and drops them only once it accepts them. A cluster is represented by
//! the centroids of four of its elements, one from each quarter of its median splits; a
//! pair whose stand-ins see nothing of each other is tested again from those elements'
//! corners ([`corners_see`]), and refined (`refine.rs`) only when some corner sees the
//! other end. A pair that neither sees is tested once more by segments between points
//! drawn at random on the two ends ([`sampled_sight`]): fixed points miss a slot that some
//! of an end sees through (a tread under a desk sees the ceiling between the desk and the
//! seats behind it), and a pair dropped for it loses its light for certain.

use super::oracle::CORNER_INSET;
use super::tree::Tree;
use crate::geometry::Patch;
use crate::random::Rng;
use crate::transfer::occlusion::{POINTS, fraction_between, polygon_points, visible_fraction};
use crate::visibility::{Blocker, PACKET, Segment, Visibility};
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
    let chosen = chosen(tree, id, towards);
    std::array::from_fn(|k| {
        chosen.get(k % chosen.len().max(1)).map_or((tree.node(id).centre(), u32::MAX), |p| (p.centroid, p.face))
    })
}

/// True when some corner of the elements that stand for `p` (seen from `q`'s centre) sees
/// some corner of those standing for `q`: corner `k` of each of one end's four to corner
/// `k` of the other's, the corners pulled [`CORNER_INSET`] towards their centroids; with
/// the rays it took (4 to 64). A cluster with no element to stand for it is taken to see.
/// Four centroids do not stand for a cluster's view: the one element of a chair's base that
/// faces the ceiling is its top, whose centroid lies under the seat while its rim sees the
/// ceiling (`docs/hierarchy.md`, "Occluded cluster links"); a room's elements behind a wall
/// see nothing from their corners either.
pub fn corners_see(visibility: &Visibility, tree: &Tree, p: u32, q: u32, blocker: &mut Blocker) -> (bool, usize) {
    let (a, b) = (tree.node(p), tree.node(q));
    let (from, to) = (standing_for(tree, p, b.centre()), standing_for(tree, q, a.centre()));
    if from.is_empty() || to.is_empty() {
        return (true, 0);
    }
    let mut rays = 0;
    for k in 0..POINTS {
        let v = fraction_between(visibility, &corners(&from, k), &corners(&to, k), blocker);
        rays += v.rays;
        if v.fraction > 0.0 {
            return (true, rays);
        }
    }
    (false, rays)
}

/// The elements standing for node `id` as seen from `towards`: the element itself, or a
/// cluster's [`chosen`] ones.
fn standing_for(tree: &Tree, id: u32, towards: DVec3) -> Vec<&Patch> {
    match tree.node(id).patch() {
        Some(patch) => vec![patch],
        None => chosen(tree, id, towards),
    }
}

/// Corner `k` of each of four elements (taken in turn from `elements`), pulled
/// [`CORNER_INSET`] towards its centroid, with its face.
fn corners(elements: &[&Patch], k: usize) -> [(DVec3, u32); POINTS] {
    std::array::from_fn(|j| {
        let patch = elements[j % elements.len()];
        let v = patch.polygon.vertices();
        (v[k % v.len()].lerp(patch.centroid, CORNER_INSET), patch.face)
    })
}

/// Up to four elements of cluster `id` that face `towards`, taken in turn from the quarters
/// of its median splits (the first elements when none faces).
fn chosen(tree: &Tree, id: u32, towards: DVec3) -> Vec<&Patch> {
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
    in_turn(pool)
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

/// The visible fraction of [`PACKET`] segments between points drawn uniformly on the faces of
/// nodes `p` and `q` turned to each other, and the rays it took: an estimate without bias
/// of the share of such segments that are free, where fixed points found none (`refine.rs`).
/// The draws are keyed by the two ends' places, not their node ids, so that a linking does
/// not depend on the order in which the tree was split (a part's linking, `model/part_rows.rs`).
pub fn sampled_sight(visibility: &Visibility, tree: &Tree, p: u32, q: u32, blocker: &mut Blocker) -> (f64, usize) {
    let (a, b) = (tree.node(p).centre(), tree.node(q).centre());
    let mut rng = Rng::stream(place_key(tree, p), place_key(tree, q));
    let mut segments: [Segment; PACKET] = [(a, b, [u32::MAX; 2]); PACKET];
    let mut n = 0;
    for _ in 0..PACKET {
        let from = drawn(tree, p, b, &mut rng);
        let to = drawn(tree, q, a, &mut rng);
        if let (Some((x, f)), Some((y, g))) = (from, to) {
            segments[n] = (x, y, [f, g]);
            n += 1;
        }
    }
    let free = visibility.visible_together(&segments[..n], blocker).count_ones();
    (f64::from(free) / PACKET as f64, n)
}

/// A point drawn uniformly on the faces of node `id` turned to `towards`, with its face: from
/// a cluster down to one of its elements, each child by its projected area towards
/// `towards`; none when no face is turned to it.
fn drawn(tree: &Tree, id: u32, towards: DVec3, rng: &mut Rng) -> Option<(DVec3, u32)> {
    let mut at = id;
    loop {
        let node = tree.node(at);
        if let Some(patch) = node.patch() {
            let x = patch.polygon.point_at(rng.uniform(), rng.uniform(), rng.uniform());
            return ((towards - x).dot(patch.normal) > 0.0).then_some((x, patch.face));
        }
        let u = (towards - node.centre()).normalize_or_zero();
        let children = tree.children(at);
        let total: f64 = children.iter().map(|&c| tree.projected(c, u)).sum();
        if total <= 0.0 {
            return None;
        }
        let mut pick = rng.uniform() * total;
        let last = *children.last()?;
        at = children
            .iter()
            .copied()
            .find(|&c| {
                pick -= tree.projected(c, u);
                pick < 0.0
            })
            .unwrap_or(last);
    }
}

/// A key of node `id`'s box, the same whatever its id.
fn place_key(tree: &Tree, id: u32) -> u64 {
    let node = tree.node(id);
    [node.lo, node.hi]
        .iter()
        .flat_map(|v| [v.x, v.y, v.z])
        .fold(0, |key: u64, c| Rng::stream(key, c.to_bits()).next_u64())
}
