//! Issue 34: elements facing each other across a slot narrower than the smallest size are
//! split toward each other before the linking (`kernel/hierarchy/slots.rs`,
//! `docs/design.md` §3b, "Slots"). A 1 × 0.5 m panel, 2 cm thick, stands 3 cm before a wall
//! of a closed 2 m room: the panel's back and the wall behind it are cut down to the slot's
//! width (a quarter of the smallest size at most), the floor is not. Without the rule no
//! leaf is finer than the smallest size, and the office's slots read 30–50 % bright (its
//! hard probes: docs/accuracy.md, "Slots"). The panel's 2 cm rims are cut into strips
//! (`ConvexPolygon::split_even`); cut by their edges' midpoints they were slivers 50 times
//! as long as wide.

use super::{PATCH_SIZE, longest_edge, room_with};
use glam::DVec3;
use ugo::geometry::Patch;

#[test]
fn the_two_faces_of_a_slot_are_cut_to_its_width() {
    let h = room_with("panel", DVec3::new(0.5, 0.5, 1.95), DVec3::new(1.5, 1.0, 1.97));
    let leaves = h.leaf_mesh();
    let longest = |filter: &dyn Fn(DVec3, DVec3) -> bool| {
        let edges: Vec<f64> =
            leaves.patches.iter().filter(|p| filter(p.centroid, p.normal)).map(longest_edge).collect();
        (edges.iter().copied().fold(f64::INFINITY, f64::min), edges.len())
    };
    let behind = |c: DVec3| (0.5..1.5).contains(&c.x) && (0.5..1.0).contains(&c.y);
    let (back, n_back) = longest(&|c, n| n.z > 0.9 && (c.z - 1.97).abs() < 1e-9);
    let (wall, n_wall) = longest(&|c, n| n.z < -0.9 && (c.z - 2.0).abs() < 1e-9 && behind(c));
    // the floor's middle, away from the room's concave edges (`edges.rs`) and the panel
    let middle = |c: DVec3| (0.5..1.5).contains(&c.x) && (0.3..1.5).contains(&c.z);
    let (floor, _) = longest(&|c, n| n.y > 0.9 && c.y.abs() < 1e-9 && middle(c));
    eprintln!(
        "slot of 3 cm: the panel's back {n_back} leaves, finest {back:.4} m; the wall behind {n_wall}, finest {wall:.4} m; the floor's finest {floor:.4} m"
    );
    assert!(back < 0.5 * PATCH_SIZE && wall < 0.5 * PATCH_SIZE, "{back}, {wall}");
    // the panel's 2 cm rims, cut into strips (`ConvexPolygon::split_even`), not slivers
    let elongation = |p: &Patch| longest_edge(p).powi(2) / p.area;
    let most = leaves.patches.iter().map(elongation).fold(0.0, f64::max);
    let rims = leaves.patches.iter().filter(|p| p.normal.z.abs() < 0.1 && (p.centroid.z - 1.96).abs() < 0.011).count();
    eprintln!("{rims} leaves on the panel's rims; every leaf at most {most:.1} times as long as wide");
    assert!(most < 8.0, "a sliver: {most}");
    assert!(floor > 0.4 * PATCH_SIZE, "the floor, far from any slot: {floor}");
}

#[test]
fn a_slot_is_cut_near_its_mouth_and_not_in_its_depth() {
    // a 1.5 m mat, 1 cm thick, lies 1 cm above the floor: the floor under it is cut near
    // the mat's edges (within 5.7 gaps of the mouth, and the elements that reach there),
    // not under its middle, where almost no light arrives: there its leaves are the
    // smallest size's (0.0625 m from 1 m roots), and 0.0156 m when the depth is cut too
    let h = room_with("mat", DVec3::new(0.25, 0.01, 0.25), DVec3::new(1.75, 0.02, 1.75));
    let floor: Vec<(f64, f64)> = h
        .leaf_mesh()
        .patches
        .iter()
        .filter(|p| p.normal.y > 0.9 && p.centroid.y.abs() < 1e-9)
        .map(|p| {
            let inside = [p.centroid.x - 0.25, 1.75 - p.centroid.x, p.centroid.z - 0.25, 1.75 - p.centroid.z];
            let edge = longest_edge(p);
            (inside.into_iter().fold(f64::INFINITY, f64::min), edge)
        })
        .collect();
    let finest = |keep: &dyn Fn(f64) -> bool| {
        floor.iter().filter(|(d, _)| keep(*d)).map(|(_, e)| *e).fold(f64::INFINITY, f64::min)
    };
    let (mouth, depth) = (finest(&|d| (0.0..0.05).contains(&d)), finest(&|d| d > 0.3));
    eprintln!("a 1 cm slot: the floor's finest leaf by the mat's edge {mouth:.4} m, under its middle {depth:.4} m");
    assert!(mouth < 0.3 * PATCH_SIZE, "by the edge: {mouth}");
    assert!(depth > 0.45 * PATCH_SIZE, "under the middle, as far from any slot: {depth}");
}

#[test]
fn no_leaf_of_the_wall_straddles_the_lines_of_a_board_before_it() {
    // a 1 m board, 2.5 cm thick, 2 cm before the wall z = 2 of the 2 m room, its faces from
    // y = 0.715 to 0.74 (a desk top's back edge): every leaf of the wall behind it lies
    // wholly above or below each of those lines (`cuts.rs`). Straddling one, a leaf sends
    // the mean of the lit wall above into the slot below (docs/accuracy.md, "A slot behind
    // a desk"); the roots' middles fall at 0.5 and 1 m, so without the cuts the leaves
    // across 0.715 and 0.74 are the splits' own.
    let h = room_with("board", DVec3::new(0.5, 0.715, 1.955), DVec3::new(1.5, 0.74, 1.98));
    let leaves = h.leaf_mesh();
    let wall: Vec<&Patch> = leaves
        .patches
        .iter()
        .filter(|p| p.normal.z < -0.9 && (p.centroid.z - 2.0).abs() < 1e-9 && (0.5..1.5).contains(&p.centroid.x))
        .collect();
    let across = |line: f64| {
        wall.iter()
            .filter(|p| {
                let (lo, hi) =
                    p.polygon.vertices().iter().fold((f64::MAX, f64::MIN), |(l, h), v| (l.min(v.y), h.max(v.y)));
                lo < line - 1e-9 && hi > line + 1e-9
            })
            .count()
    };
    eprintln!(
        "{} leaves of the wall behind the board; across y = 0.715: {}, across 0.74: {}",
        wall.len(),
        across(0.715),
        across(0.74)
    );
    assert!(!wall.is_empty());
    assert_eq!((across(0.715), across(0.74)), (0, 0));
}
