//! Concave edges (`docs/design.md` §3b, "Concave edges"): where a room's walls, floor and
//! ceiling meet, each sees the other at large factors within a few centimetres of the
//! edge, and the light falls off toward it over the distance from it, not over the
//! smallest size: leaves of the smallest size carry their mean into the corner (the
//! office's trihedral corners read 5 % bright 2 cm from two walls, `docs/hierarchy.md`,
//! "Concave edges of the room"). Before any link is made (`grading.rs`), two wholly
//! exposed elements that meet at a concave edge, or nearly do, are split toward each
//! other, down to their distance but not below [`EDGE_FINEST`] of the smallest size. An
//! element any part of which lies inside or against a solid is left to the linking (§3b,
//! "Contacts"): graded, its pieces under the solid had no light of their own to read. Nor
//! are the elements of narrow surfaces ([`EDGE_NARROWEST`]). Toward a thin face, narrower
//! than [`EDGE_FINEST`] of the smallest size (a whiteboard's 2 cm underside against a
//! wall), only the wide side is graded, down to the thin face's width ([`NARROW_FINEST`]),
//! even where it straddles the contact: the contact's cuts part it first (`cuts.rs`), and
//! the thin face, which sees it at large factors, otherwise reads its mean
//! (`docs/accuracy.md`, "A whiteboard on a wall": the wall 1 cm under the board +3.7 %).

use super::node::longest_edge;
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

/// The element of the pair `(p, q)` to split, if they meet at a concave edge, in front of
/// each other and nearer than `patch_size` (m): the larger of those graded toward the
/// other ([`graded_toward`]), down to their distance (0 at a shared edge) but not below
/// [`EDGE_FINEST`] of `patch_size`; toward a thin face, down to its width (a 2 cm
/// underside: 2 cm) but not below [`NARROW_FINEST`] of `patch_size`. An element of the
/// smallest size is split below it only if the pair sees something of each other. With
/// the rays it took.
pub fn to_split(tree: &Tree, visibility: &Visibility, patch_size: f64, p: u32, q: u32) -> (Option<u32>, usize) {
    let (a, b) = (tree.node(p), tree.node(q));
    let (Some(pa), Some(pb)) = (a.patch(), b.patch()) else { return (None, 0) };
    let distance = a.box_distance(b);
    if distance >= patch_size || !facing(pa, pb) {
        return (None, 0);
    }
    let narrowest = width(tree, p).min(width(tree, q)).max(NARROW_FINEST * patch_size);
    let finest = distance.max((EDGE_FINEST * patch_size).min(narrowest));
    let toward = |n: u32| graded_toward(tree, n, if n == p { q } else { p }, patch_size);
    let Some((n, smallest)) = split_toward(tree, (p, q), finest, patch_size, toward) else { return (None, 0) };
    if !smallest {
        return (Some(n), 0);
    }
    let (seen, _, rays) = sight(visibility, pa, pb, &mut Blocker::default());
    (if seen == Sight::Occluded { None } else { Some(n) }, rays)
}

/// True when element `n` is graded toward element `m` across their concave edge: `n` lies
/// on a wide surface ([`EDGE_NARROWEST`]), `m` is wholly exposed, and either `n` is wholly
/// exposed too (a room's walls, floor and ceiling where they meet; a floor before a low
/// panel) or `m` is thin, narrower than [`EDGE_FINEST`] of the smallest size (a
/// whiteboard's 2 cm underside against a wall). Then `n` may straddle a contact (the wall's
/// element under the whiteboard): it splits along the contact's cuts first (`cuts.rs`), so
/// that no piece straddles it, and its exposed pieces are graded.
/// Merely narrow faces are not enough: a surface's width is its root's, and the open box's
/// 0.3 m blocks, cut into roots of 0.15 m, would grade the floor at their feet into leaves
/// that read 80 % off the uniform kernel's (`docs/hierarchy.md`, "Toward narrow faces").
fn graded_toward(tree: &Tree, n: u32, m: u32, patch_size: f64) -> bool {
    let (a, b) = (tree.node(n), tree.node(m));
    let thin = width(tree, m) < EDGE_FINEST * patch_size;
    wide(tree, n, patch_size) && b.wholly_exposed() && (thin || a.wholly_exposed())
}

/// Elements graded toward a thin face split down to its width, but not below this
/// share of the smallest size: a face a millimetre thick would cut its neighbour to a
/// millimetre. The office's wall 1 cm under its whiteboard: +0.82 % graded to a quarter of
/// the smallest size (3.75 cm), +0.32 % to the board's 2 cm (`docs/hierarchy.md`, "Toward
/// narrow faces").
pub const NARROW_FINEST: f64 = 1.0 / 16.0;

/// Surfaces narrower than this many smallest sizes are not graded: the band graded on
/// each side of an edge, a smallest size wide, would cover all of them (a seat's parts, a
/// riser, a book). The lecture hall: 196,573 leaves graded on every surface, 109,477 so;
/// the office's hard probes 27 and 28 beyond 1 % (`docs/hierarchy.md`, "Narrow surfaces").
pub const EDGE_NARROWEST: f64 = 2.0;

/// True when element `n` lies on a surface at least [`EDGE_NARROWEST`] smallest sizes
/// `patch_size` (m) wide.
fn wide(tree: &Tree, n: u32, patch_size: f64) -> bool {
    width(tree, n) >= EDGE_NARROWEST * patch_size
}

/// The width of the surface element `n` lies on, m: its root element's area over its
/// longest edge (0 for a cluster).
fn width(tree: &Tree, n: u32) -> f64 {
    let Some(root) = tree.node(tree.root(n)).patch() else { return 0.0 };
    root.area / longest_edge(&root.polygon)
}
