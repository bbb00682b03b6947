//! Issue 36: rooms behind walls are not linked element by element. A pair of clusters
//! whose stand-ins see nothing of each other was refined down to its elements whatever its
//! error (2026-12-05, for a chair's base whose rim sees the ceiling past its seat), and in
//! a building every pair of rooms behind a wall is such a pair: the floor of 28 rooms
//! was refused at 14.2 GiB of candidate pairs (`docs/performance.md`, "The building"). Such
//! a pair is now tested again from the corners of the elements its stand-ins lie on and
//! dropped when none sees the other end (`sight.rs`, `corners_see`); the chair's case
//! stays in `overhang.rs`.
//!
//! Here two closed furnished rooms 20 m apart, roots and leaves of 1 m: the second room
//! may cost at most the rays of the first (measured: 240,986 rays for one room; for two,
//! 507,416 when the pairs between the rooms were refined, 469,668 now).

use super::{hierarchy, options};
use crate::support::{furnace, surface};
use glam::DVec3;
use ugo::directions::DirectionSet;
use ugo::geometry::{Emission, Shape};
use ugo::scene::Scene;

/// `count` closed rooms of 3 × 2.5 × 3 m, [`SPACING`] apart along x, each with a table and a
/// shelf (ρ 0.5, the rooms' walls emitting 1 cd/m²).
fn rooms(count: usize) -> Scene {
    let mut scene = furnace(1.0, 0.5, 1.0, 1.0);
    scene.surfaces.clear();
    let boxed = |lo: [f64; 3], hi: [f64; 3], x: f64| Shape::Box {
        min: DVec3::from(lo) + DVec3::X * x,
        max: DVec3::from(hi) + DVec3::X * x,
        rotate_y_deg: 0.0,
    };
    for i in 0..count {
        let x = i as f64 * SPACING;
        let emitting = Some(Emission::Luminance(1.0));
        scene.surfaces.push(surface("room", boxed([0.0; 3], [3.0, 2.5, 3.0], x), 0, true, emitting));
        scene.surfaces.push(surface("table", boxed([1.0, 0.0, 1.0], [2.0, 0.7, 1.6], x), 0, false, None));
        scene.surfaces.push(surface("shelf", boxed([0.1, 0.0, 2.4], [1.1, 1.8, 2.8], x), 0, false, None));
    }
    scene
}

/// The rooms' spacing, m: far enough that the pairs between them are accepted by their
/// error bound before visibility decides.
const SPACING: f64 = 20.0;

#[test]
fn a_second_room_behind_walls_costs_no_more_rays_than_the_first() {
    let rays = |count| hierarchy(&rooms(count), 1.0, DirectionSet::single(), options(1e-2, 1.0)).work().rays;
    let (one, two) = (rays(1), rays(2));
    eprintln!("occlusion rays: {one} for one room, {two} for two");
    assert!(two <= 2 * one, "{two} rays for two rooms against {one} for one");
}
