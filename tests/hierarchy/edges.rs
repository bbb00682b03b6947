//! Issue 34: wholly exposed elements that meet at a concave edge are split toward it
//! before the linking (`kernel/hierarchy/edges.rs`, `docs/design.md` §3b, "Concave
//! edges"); elements partly inside or against a solid are not. A 0.4 m block stands on
//! the floor of a closed 2 m room: the floor and the ceiling along the walls are cut down
//! to a quarter of the smallest size, the block's sides at its foot, and the floor's
//! 1 m root under it, are not. Without the rule no leaf along the walls is finer than the
//! smallest size, and the office's room corners read 5 % bright 2 cm from two walls
//! (`docs/accuracy.md`, "Concave edges of the room").

use super::{PATCH_SIZE, hierarchy, longest_edge, options, room_with};
use crate::support::{furnace, surface};
use glam::DVec3;
use ugo::directions::DirectionSet;
use ugo::geometry::{Patch, Shape};

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

/// A panel standing on the floor, facing `+x` when `u × v` does: from `origin` along `u`, `v`.
fn panel(name: &str, origin: DVec3, u: DVec3, v: DVec3) -> ugo::geometry::Surface {
    surface(name, Shape::Rectangle { origin, edge_u: u, edge_v: v }, 0, false, None)
}

/// Two upright one-sided panels 1 m long stand on the floor of the 2 m room, apart:
/// one 0.15 m high (narrower than two smallest sizes, 0.24 m), facing `+x` at x = 0.7,
/// and one 0.3 m high facing `−x` at x = 1.3. The floor before the high one, and its foot,
/// are cut to a quarter of the smallest size; before the low one only the floor is: the
/// low panel is not graded (`edges::EDGE_NARROWEST`: graded, it would be cut all over),
/// but the wide floor is graded toward it, as a wall toward a whiteboard's underside
/// (`edges::graded_toward`; before, neither side was).
#[test]
fn a_narrow_surface_is_not_graded_and_the_floor_before_it_is() {
    let mut room = furnace(2.0, 0.5, 1.0, 10.0);
    let (up, along) = (DVec3::Y, DVec3::Z);
    room.surfaces.push(panel("low", DVec3::new(0.7, 0.0, 0.5), 0.15 * up, along));
    room.surfaces.push(panel("high", DVec3::new(1.3, 0.0, 0.5), along, 0.3 * up));
    let h = hierarchy(&room, 1.0, DirectionSet::single(), options(1e-2, PATCH_SIZE));
    let leaves = h.leaf_mesh().patches;
    let middle = |p: &Patch| (0.7..1.3).contains(&p.centroid.z);
    let on_floor = |p: &Patch| p.normal.y > 0.9 && p.centroid.y.abs() < 1e-9 && middle(p);
    let (before_low, _) = finest(&leaves, &|p| on_floor(p) && (0.7..0.8).contains(&p.centroid.x));
    let (before_high, _) = finest(&leaves, &|p| on_floor(p) && (1.2..1.3).contains(&p.centroid.x));
    let (low, n_low) = finest(&leaves, &|p| p.normal.x > 0.9 && (p.centroid.x - 0.7).abs() < 1e-9 && middle(p));
    let (high, _) = finest(&leaves, &|p| p.normal.x < -0.9 && (p.centroid.x - 1.3).abs() < 1e-9 && middle(p));
    eprintln!(
        "the floor before the low panel {before_low:.4} m, the low panel {n_low} leaves, finest {low:.4} m; \
         the floor before the high panel {before_high:.4} m, the high panel {high:.4} m"
    );
    assert!(before_high < 0.3 * PATCH_SIZE && high < 0.3 * PATCH_SIZE, "the high panel's foot: {before_high}, {high}");
    assert!(before_low < 0.3 * PATCH_SIZE && low > 0.4 * PATCH_SIZE, "the low panel's foot: {before_low}, {low}");
}
