//! Slots (`docs/design.md` §3b, "Slots"): two elements facing each other across a gap
//! narrower than the smallest element size (a modesty panel 5 cm before a wall, books a few
//! millimetres apart) exchange most of their light across it, and that light falls off
//! over the gap's width, not over the smallest size. Before any link is made
//! (`grading.rs`), such pairs are split toward each other, down to the gap's width but not
//! below [`SLOT_FINEST`] of the smallest size, near the slot's mouth only: deep in a slot
//! (a rug's underside, a metre from its edge) almost no light arrives.

use super::oracle::{sample_points, split_toward};
use super::sight::{Sight, sight};
use super::tree::Tree;
use crate::geometry::{Patch, facing};
use crate::visibility::{Blocker, Visibility};

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

/// The element of the facing pair `(p, q)` to split, if they face each other across a
/// slot: both exposed, in front of each other, apart by more than [`TOUCHING`] and less
/// than `patch_size`; the larger first, down to the gap's width but not below
/// [`SLOT_FINEST`] of `patch_size`. An element of the smallest size is split below it only
/// if the pair sees something of each other; a larger one is split unseen (blocked
/// segments between large elements prove nothing: the wall behind a cabinet's plinth,
/// 1 m wide, sees the plinth only under the cabinet), and only if it lies near the slot's
/// mouth, not deep in it ([`deep_in_slot`]). With the rays it took.
pub fn to_split(tree: &Tree, visibility: &Visibility, patch_size: f64, p: u32, q: u32) -> (Option<u32>, usize) {
    let (a, b) = (tree.node(p), tree.node(q));
    let (Some(pa), Some(pb)) = (a.patch(), b.patch()) else { return (None, 0) };
    let width = a.box_distance(b);
    if width <= TOUCHING || width >= patch_size || a.exposed <= 0.0 || b.exposed <= 0.0 || !facing(pa, pb) {
        return (None, 0);
    }
    let finest = width.max(SLOT_FINEST * patch_size);
    let Some((n, smallest)) = split_toward(tree, (p, q), finest, patch_size, |_| true) else { return (None, 0) };
    if !smallest {
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
