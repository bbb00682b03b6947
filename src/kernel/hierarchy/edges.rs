//! Concave edges (`docs/design.md` §3b, "Concave edges"): where a room's walls, floor and
//! ceiling meet, each sees the other at large factors within a few centimetres of the
//! edge, and the light falls off toward it over the distance from it, not over the
//! smallest size: leaves of the smallest size carry their mean into the corner (the
//! office's trihedral corners read 5 % bright 2 cm from two walls, `docs/hierarchy.md`,
//! "Concave edges of the room"). Before any link is made (`grading.rs`), two wholly
//! exposed elements that meet at a concave edge, or nearly do, are split toward each
//! other, down to their distance but not below [`EDGE_FINEST`] of the smallest size. An
//! element any part of which lies inside or against a solid is left to the linking (§3b,
//! "Contacts"): graded, its pieces under the solid had no light of their own to read.

use super::oracle::split_toward;
use super::sight::{Sight, sight};
use super::tree::Tree;
use crate::geometry::facing;
use crate::visibility::{Blocker, Visibility};

/// Two elements meet at a concave edge when their normals' dot product is below this
/// (apart by more than 60°) and each lies in front of the other.
pub const EDGE_FACING: f64 = 0.5;

/// Elements at a concave edge split down to this share of the smallest size at most, as
/// across a slot (`slots::SLOT_FINEST`).
pub const EDGE_FINEST: f64 = 0.25;

/// The element of the pair `(p, q)` to split, if they meet at a concave edge: both wholly
/// exposed, in front of each other, nearer than `patch_size` (m); the larger first, down
/// to their distance (0 at a shared edge) but not below [`EDGE_FINEST`] of `patch_size`.
/// An element of the smallest size is split below it only if the pair sees something of
/// each other. With the rays it took.
pub fn to_split(tree: &Tree, visibility: &Visibility, patch_size: f64, p: u32, q: u32) -> (Option<u32>, usize) {
    let (a, b) = (tree.node(p), tree.node(q));
    let (Some(pa), Some(pb)) = (a.patch(), b.patch()) else { return (None, 0) };
    let distance = a.box_distance(b);
    if distance >= patch_size || !a.wholly_exposed() || !b.wholly_exposed() || !facing(pa, pb) {
        return (None, 0);
    }
    let finest = distance.max(EDGE_FINEST * patch_size);
    let Some((n, smallest)) = split_toward(tree, p, q, finest, patch_size) else { return (None, 0) };
    if !smallest {
        return (Some(n), 0);
    }
    let (seen, _, rays) = sight(visibility, pa, pb, &mut Blocker::default());
    (if seen == Sight::Occluded { None } else { Some(n) }, rays)
}
