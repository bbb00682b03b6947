//! One ray for a patch of small light (`transfer::occlusion::sample_one`, used by the error
//! bars' gathers: `readout/error_bar.rs`, `ONE_RAY`): over its four picks it hands on, on
//! average, exactly the fraction of the patch's stratified points that see, so the estimate
//! is unbiased. Checked from a floor point beside the open box's tall block to every patch
//! of the room, a share of which the blocks hide in part.

use glam::DVec3;
use std::cell::Cell;
use std::path::Path;
use ugo::geometry::Mesh;
use ugo::scene::Scene;
use ugo::transfer::occlusion::{POINTS, polygon_points, sample_one};
use ugo::visibility::{NO_BLOCKER, Sight, SightTo, Visibility};

#[test]
fn one_ray_over_its_picks_sees_what_the_points_see() {
    let scene = Scene::load(Path::new("cases/open-box.toml")).unwrap();
    let mesh = Mesh::build(&scene.surfaces, 0.1);
    let v = Visibility::build_for(&scene.surfaces, &mesh);
    let floor = mesh.patches.iter().find(|s| s.normal.y > 0.9 && s.centroid.y < 1e-6).expect("a floor patch");
    let p = DVec3::new(0.45, 1e-3, 0.45);
    let (mut partly, blocker) = (0, Cell::new(NO_BLOCKER));
    for t in mesh.patches.iter().filter(|t| (p - t.centroid).dot(t.normal) > 0.0) {
        let sight = SightTo::new(&v, p, [floor.face, t.face], &blocker);
        let seen = polygon_points(&t.polygon).iter().filter(|&&x| sight.sees(x)).count();
        let mut handed = 0.0;
        let rays: usize = (0..POINTS as u64)
            .map(|pick| {
                sample_one(&t.polygon, &sight, pick, &mut |piece, fraction| {
                    assert_eq!(piece.vertices(), t.polygon.vertices(), "the patch whole");
                    handed += fraction;
                })
            })
            .sum();
        assert_eq!(rays, POINTS, "one ray a pick");
        assert_eq!(handed / POINTS as f64, seen as f64 / POINTS as f64, "patch at {}", t.centroid);
        partly += usize::from(seen > 0 && seen < POINTS);
    }
    assert!(partly >= 5, "only {partly} patches partly hidden");
}
