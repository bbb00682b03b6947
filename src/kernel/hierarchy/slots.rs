//! Slots (`docs/design.md` §3b, "Slots"): two elements facing each other across a gap
//! narrower than the smallest element size (a modesty panel 5 cm before a wall, books a few
//! millimetres apart) exchange most of their light across it, and that light falls off
//! over the gap's width, not over the smallest size. Before any link is made, such pairs
//! are split toward each other, down to the gap's width but not below [`SLOT_FINEST`] of
//! the smallest size, near the slot's mouth only: deep in a slot (a rug's underside, a
//! metre from its edge) almost no light arrives. They are found from the geometry alone
//! (the cluster tree walked in pairs of nodes nearer than the smallest size, then rays
//! between and along the faces of the elements that would split below it), so that every
//! process, and every part of a partitioned linking, cuts the same tree. The linking then
//! refines into those elements wherever the oracle asks: an element already split may
//! always be refined (`Tree::can_split`).

use super::brightness::Brightness;
use super::node::{NONE, Node};
use super::oracle::{larger_first, sample_points};
use super::refine::{children_pairs, split_node};
use super::sight::{Sight, sight};
use super::tree::{Exposure, Tree};
use crate::geometry::{Patch, facing};
use crate::visibility::{Blocker, Visibility};
use rayon::prelude::*;

/// Two elements face each other across a slot when their normals' dot product is below
/// minus this.
pub const SLOT_FACING: f64 = 0.9;

/// Elements across a slot split down to this share of the smallest size at most: the
/// office's slots (a desk top's back edge 2 cm from the wall, a modesty panel 5 cm from it,
/// books a few millimetres apart) were measured at a quarter (`docs/hierarchy.md`, "Slots").
pub const SLOT_FINEST: f64 = 0.25;

/// Elements whose bounding boxes are nearer than this, m, touch (a contact, or an
/// element and its back) rather than face each other across a slot.
pub const TOUCHING: f64 = 1e-4;

/// Splits the elements of `tree` that face each other across a slot narrower than
/// `patch_size` (m), new nodes taking their parent's `brightness`; `exposed` measures the
/// exposed area of new elements. Returns the occlusion rays traced.
pub fn split_slots(
    tree: &mut Tree,
    brightness: &mut Brightness,
    visibility: &Visibility,
    exposed: &Exposure<'_>,
    patch_size: f64,
) -> usize {
    let mut rays_traced = 0;
    let mut pairs = facing_pairs(tree, patch_size);
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

/// The pairs of distinct elements whose bounding boxes are nearer than `patch_size` (m)
/// and whose normals are opposed, found by walking the cluster tree in pairs of nodes.
fn facing_pairs(tree: &Tree, patch_size: f64) -> Vec<(u32, u32)> {
    let (mut out, top) = (Vec::new(), tree.top());
    let mut stack = if top == NONE { Vec::new() } else { vec![(top, top)] };
    while let Some((a, b)) = stack.pop() {
        let (na, nb) = (tree.node(a), tree.node(b));
        if a != b && na.box_distance(nb) >= patch_size {
            continue;
        }
        match (na.patch(), nb.patch()) {
            (Some(pa), Some(pb)) => {
                if a != b && pa.normal.dot(pb.normal) < -SLOT_FACING {
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

/// The element of the facing pair `(p, q)` to split, if they face each other across a
/// slot: both exposed, in front of each other, apart by more than [`TOUCHING`] and less
/// than `patch_size`; the larger first, down to the gap's width but not below
/// [`SLOT_FINEST`] of `patch_size`. An element of the smallest size is split below it only
/// if the pair sees something of each other; a larger one is split unseen (blocked
/// segments between large elements prove nothing: the wall behind a cabinet's plinth,
/// 1 m wide, sees the plinth only under the cabinet), and only if it lies near the slot's
/// mouth, not deep in it ([`deep_in_slot`]). With the rays it took.
fn to_split(tree: &Tree, visibility: &Visibility, patch_size: f64, p: u32, q: u32) -> (Option<u32>, usize) {
    let (a, b) = (tree.node(p), tree.node(q));
    let (Some(pa), Some(pb)) = (a.patch(), b.patch()) else { return (None, 0) };
    let width = a.box_distance(b);
    if width <= TOUCHING || width >= patch_size || a.exposed <= 0.0 || b.exposed <= 0.0 || !facing(pa, pb) {
        return (None, 0);
    }
    let finest = width.max(SLOT_FINEST * patch_size);
    let order = larger_first(p, q, a.area, b.area);
    let Some(n) = order.into_iter().find(|&n| tree.can_split(n, finest)) else { return (None, 0) };
    if !tree.node(n).is_leaf() || tree.can_split(n, patch_size) {
        return (Some(n), 0);
    }
    let (seen, _, rays) = sight(visibility, pa, pb, &mut Blocker::default());
    if seen == Sight::Occluded {
        return (None, rays);
    }
    let gap = (pb.centroid - pa.centroid).dot(pa.normal).abs();
    let (patch, other) = if n == p { (pa, pb) } else { (pb, pa) };
    let (deep, more) = deep_in_slot(visibility, patch, other, gap);
    (if deep { None } else { Some(n) }, rays + more)
}

/// Grazing rays from an element in a slot leave it at [`GRAZING`] degrees from its normal.
pub const GRAZING: f64 = 80.0;

/// Azimuths of the grazing rays from each sample point.
const AZIMUTHS: usize = 8;

/// True when `patch` lies deep in the slot between it and `other`, `gap` apart (m): from
/// every sample point of `patch` (`oracle::sample_points`), and from the point across the
/// gap from it, every grazing ray meets a surface before it has crossed the gap, so both
/// faces reach farther than `gap · tan` [`GRAZING`] (5.7 gaps) in every direction, and
/// almost no light arrives from the slot's mouth (a rug's underside a metre from its edge).
/// With the rays it took.
fn deep_in_slot(visibility: &Visibility, patch: &Patch, other: &Patch, gap: f64) -> (bool, usize) {
    let frame = patch.frame();
    let (along, across) = (GRAZING.to_radians().cos(), GRAZING.to_radians().sin());
    let reach = 1.5 * gap / along;
    let mut rays = 0;
    for x in sample_points(patch) {
        let across_gap = x + gap * frame.normal;
        for k in 0..AZIMUTHS {
            let phi = std::f64::consts::TAU * k as f64 / AZIMUTHS as f64;
            let sideways = across * (phi.cos() * frame.tangent + phi.sin() * frame.bitangent);
            let out = x + reach * (along * frame.normal + sideways);
            let back = across_gap + reach * (sideways - along * frame.normal);
            rays += 2;
            if visibility.visible(x, out, [patch.face; 2]) || visibility.visible(across_gap, back, [other.face; 2]) {
                return (false, rays);
            }
        }
    }
    (true, rays)
}
