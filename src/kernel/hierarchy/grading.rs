//! Grading before the linking (`docs/design.md` §3b, "Slots" and "Concave edges"): pairs of
//! elements nearer than the smallest size whose light changes over their distance are
//! split toward each other before any link is made, by the rule their normals choose:
//! facing each other across a slot (`slots.rs`), or meeting at a concave edge
//! (`edges.rs`). The pairs are found from the geometry alone (the cluster tree walked in
//! pairs of nodes nearer than the smallest size, then rays between the elements that would
//! split below it), so that every process, and every part of a partitioned linking, cuts
//! the same tree. The linking then refines into those elements wherever the oracle asks:
//! an element already split may always be refined (`Tree::can_split`).

use super::brightness::Brightness;
use super::edges::{self, EDGE_FACING};
use super::node::{NONE, Node};
use super::refine::{children_pairs, split_node};
use super::slots::{self, SLOT_FACING};
use super::tree::{Exposure, Tree};
use crate::visibility::Visibility;
use rayon::prelude::*;

/// Splits the elements of `tree` that a slot or a concave edge nearer than `patch_size`
/// (m) asks to, new nodes taking their parent's `brightness`; `exposed` measures the
/// exposed area of new elements. Returns the occlusion rays traced.
pub fn grade(
    tree: &mut Tree,
    brightness: &mut Brightness,
    visibility: &Visibility,
    exposed: &Exposure<'_>,
    patch_size: f64,
) -> usize {
    let mut rays_traced = 0;
    let mut pairs = near_pairs(tree, patch_size);
    while !pairs.is_empty() {
        let outcomes: Vec<(Option<u32>, usize)> =
            pairs.par_iter().map(|&(p, q)| to_split(tree, visibility, patch_size, p, q)).collect();
        let mut next = Vec::new();
        for (&(p, q), (split, rays)) in pairs.iter().zip(outcomes) {
            rays_traced += rays;
            let Some(n) = split else { continue };
            split_node(tree, brightness, n, exposed);
            children_pairs(tree, p, q, n, &mut next);
        }
        pairs = next;
    }
    rays_traced
}

/// The element of the pair `(p, q)` to split, by the rule of the angle between their
/// normals: opposed within [`SLOT_FACING`], a slot; apart by more than the angle of
/// [`EDGE_FACING`], a concave edge; nothing otherwise. With the rays it took.
fn to_split(tree: &Tree, visibility: &Visibility, patch_size: f64, p: u32, q: u32) -> (Option<u32>, usize) {
    let (Some(a), Some(b)) = (tree.node(p).patch(), tree.node(q).patch()) else { return (None, 0) };
    let cosine = a.normal.dot(b.normal);
    if cosine < -SLOT_FACING {
        slots::to_split(tree, visibility, patch_size, p, q)
    } else if cosine < EDGE_FACING {
        edges::to_split(tree, visibility, patch_size, p, q)
    } else {
        (None, 0)
    }
}

/// The pairs of distinct elements whose bounding boxes are nearer than `patch_size` (m)
/// and whose normals are apart by more than the angle of [`EDGE_FACING`], found by walking
/// the cluster tree in pairs of nodes.
pub(super) fn near_pairs(tree: &Tree, patch_size: f64) -> Vec<(u32, u32)> {
    let (mut out, top) = (Vec::new(), tree.top());
    let mut stack = if top == NONE { Vec::new() } else { vec![(top, top)] };
    while let Some((a, b)) = stack.pop() {
        let (na, nb) = (tree.node(a), tree.node(b));
        if a != b && na.box_distance(nb) >= patch_size {
            continue;
        }
        match (na.patch(), nb.patch()) {
            (Some(pa), Some(pb)) => {
                if a != b && pa.normal.dot(pb.normal) < EDGE_FACING {
                    out.push((a, b));
                }
            }
            _ if a == b => {
                let c = tree.children(a);
                stack.extend((0..c.len()).flat_map(|i| (i..c.len()).map(move |j| (c[i], c[j]))));
            }
            _ if opens_first(na, nb) => stack.extend(tree.children(a).iter().map(|&c| (c, b))),
            _ => stack.extend(tree.children(b).iter().map(|&c| (a, c))),
        }
    }
    out
}

/// True when the walk opens `a` before `b`: a cluster before an element, the larger
/// cluster of two.
fn opens_first(a: &Node, b: &Node) -> bool {
    match (a.patch(), b.patch()) {
        (None, Some(_)) => true,
        (None, None) => a.diagonal() >= b.diagonal(),
        _ => false,
    }
}
