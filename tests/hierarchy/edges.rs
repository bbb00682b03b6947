//! Issue 34: wholly exposed elements that meet at a concave edge are split toward it
//! before the linking (`kernel/hierarchy/edges.rs`, `docs/design.md` §3b, "Concave
//! edges"); elements partly inside or against a solid are not. A 0.4 m block stands on
//! the floor of a closed 2 m room: the floor and the ceiling along the walls are cut down
//! to a quarter of the smallest size, the block's sides at its foot, and the floor's
//! 1 m root under it, are not. Without the rule no leaf along the walls is finer than the
//! smallest size, and the office's room corners read 5 % bright 2 cm from two walls
//! (`docs/accuracy.md`, "Concave edges of the room").

use super::{PATCH_SIZE, longest_edge, room_with};
use glam::DVec3;
use ugo::geometry::Patch;

/// The finest leaf edge among `leaves` that pass `keep`, m, and how many passed.
fn finest(leaves: &[Patch], keep: &dyn Fn(&Patch) -> bool) -> (f64, usize) {
    let edges: Vec<f64> = leaves.iter().filter(|p| keep(p)).map(longest_edge).collect();
    (edges.iter().copied().fold(f64::INFINITY, f64::min), edges.len())
}

#[test]
fn the_room_s_edges_are_graded_and_a_block_s_foot_is_not() {
    let h = room_with("block", DVec3::new(1.2, 0.0, 1.2), DVec3::new(1.6, 0.4, 1.6));
    let leaves = h.leaf_mesh().patches;
    let along_the_wall = |p: &Patch| p.centroid.x < 0.03 && (0.2..0.8).contains(&p.centroid.z);
    let (floor, n_floor) = finest(&leaves, &|p| p.normal.y > 0.9 && p.centroid.y.abs() < 1e-9 && along_the_wall(p));
    let (ceiling, _) =
        finest(&leaves, &|p| p.normal.y < -0.9 && (p.centroid.y - 2.0).abs() < 1e-9 && along_the_wall(p));
    let (wall, _) = finest(&leaves, &|p| p.normal.x > 0.9 && p.centroid.y < 0.03 && (0.2..0.8).contains(&p.centroid.z));
    let on_block = |c: DVec3| (1.19..1.61).contains(&c.x) && (1.19..1.61).contains(&c.z) && c.y < 0.41;
    let (foot, n_foot) = finest(&leaves, &|p| p.normal.y.abs() < 0.1 && on_block(p.centroid) && p.centroid.y < 0.06);
    let beside = |c: DVec3| (1.1..1.7).contains(&c.x) && (1.1..1.7).contains(&c.z) && !on_block(c);
    let (around, _) = finest(&leaves, &|p| p.normal.y > 0.9 && p.centroid.y.abs() < 1e-9 && beside(p.centroid));
    eprintln!(
        "along the wall x = 0: the floor {n_floor} leaves, finest {floor:.4} m; the ceiling {ceiling:.4} m; the wall at the floor {wall:.4} m; \
         the block's foot {n_foot} leaves, finest {foot:.4} m; the floor around it {around:.4} m"
    );
    for (name, edge) in [("floor", floor), ("ceiling", ceiling), ("wall", wall)] {
        assert!(edge < 0.3 * PATCH_SIZE, "the {name} along a concave edge of the room: {edge}");
    }
    assert!(foot > 0.4 * PATCH_SIZE && around > 0.4 * PATCH_SIZE, "at a contact: {foot}, {around}");
    let elongation = |p: &Patch| longest_edge(p).powi(2) / p.area;
    let most = leaves.iter().map(elongation).fold(0.0, f64::max);
    assert!(most < 8.0, "a sliver: {most}");
}
