//! Each cluster child's openness along the six axis directions (`docs/design.md` (3b.8)):
//! the share of rays from the child's stand-ins facing an axis, leaning around it, that
//! reach the side of the cluster's box without meeting a surface. A cluster's facing areas
//! are its children's times their openness, and so are its vector areas (3b.9), so that
//! its projected area (3b.2) counts what a receiver outside can see of it, and its facing
//! values (3b.7) the light of those faces: the treads under a row's desks, which face the
//! ceiling as the desks' tops do, send it nothing.

use super::node::FACING;
use super::sight::stand_ins;
use super::tree::Tree;
use super::vector_areas::VectorAreas;
use crate::transfer::occlusion::POINTS;
use crate::visibility::{NO_BLOCKER, NO_FACE, Segment, Visibility};
use glam::DVec3;

/// The axis directions in the order of `Node::facing`.
const AXES: [DVec3; FACING] = [DVec3::X, DVec3::NEG_X, DVec3::Y, DVec3::NEG_Y, DVec3::Z, DVec3::NEG_Z];

/// How far a ray leans from its axis: `tan` of 40°, between the axis and the grazing
/// directions a cluster's faces send to.
const LEAN: f64 = 0.84;

/// Each node's openness within its parent cluster along each axis (1 where nothing is
/// tested), by node id, for the nodes that are members of clusters; the clusters' facing
/// areas set to their children's times it, bottom-up.
pub fn open_facing(tree: &mut Tree, visibility: &Visibility) -> Vec<[f64; FACING]> {
    let mut open = vec![[1.0; FACING]; tree.len()];
    for id in 0..tree.len() as u32 {
        if tree.node(id).patch().is_some() {
            continue;
        }
        let (lo, hi) = (tree.node(id).lo, tree.node(id).hi);
        let (mut facing, mut areas) = ([0.0; FACING], VectorAreas::default());
        for &child in tree.children(id) {
            let node = tree.node(child);
            for (c, axis) in AXES.iter().enumerate() {
                if node.facing[c] <= 0.0 {
                    continue;
                }
                open[child as usize][c] = openness(tree, visibility, child, *axis, (lo, hi));
                facing[c] += node.facing[c] * open[child as usize][c];
            }
            areas.add(&tree.vector_areas(child), &open[child as usize]);
        }
        tree.set_facing(id, facing, areas);
    }
    open
}

/// The share of [`RAYS`] rays from node `id`'s stand-ins facing `axis` that leave the box
/// `(lo, hi)` unmet: from each stand-in one leaning [`LEAN`] from the axis towards each of
/// four sides, nudged a quarter turn's third one way or the other from ray to ray.
fn openness(tree: &Tree, visibility: &Visibility, id: u32, axis: DVec3, (lo, hi): (DVec3, DVec3)) -> f64 {
    let node = tree.node(id);
    let points = stand_ins(tree, id, node.centre() + axis * (1.0 + node.diagonal()) * 1e3);
    let (t1, t2) = (axis.any_orthonormal_vector(), axis.cross(axis.any_orthonormal_vector()));
    let sides = [t1, -t1, t2, -t2];
    let segments: [Segment; RAYS] = std::array::from_fn(|r| {
        let ((p, face), side) = (points[r / SIDES], r % SIDES);
        let nudge = if (r / SIDES + side).is_multiple_of(2) { t1 + t2 } else { t1 - t2 };
        let d = (axis + LEAN * (sides[side] + 0.5 * nudge).normalize()).normalize();
        (p, p + d * exit(p, d, (lo, hi)), [face, NO_FACE])
    });
    let mut blocker = NO_BLOCKER;
    f64::from(visibility.visible_together(&segments, &mut blocker).count_ones()) / RAYS as f64
}

/// Rays from each stand-in, one towards each side of the axis.
const SIDES: usize = 4;

/// Rays per child and axis.
const RAYS: usize = POINTS * SIDES;

/// The distance along `d` from `p` (inside the box) to the box's far side, less a hair so
/// that a surface on the box's face is not met.
fn exit(p: DVec3, d: DVec3, (lo, hi): (DVec3, DVec3)) -> f64 {
    let t = (0..3)
        .filter(|&a| d[a].abs() > 1e-12)
        .map(|a| ((if d[a] > 0.0 { hi[a] } else { lo[a] }) - p[a]) / d[a])
        .fold(f64::INFINITY, f64::min);
    (t - 1e-4).max(0.0)
}
