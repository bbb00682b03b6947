//! Closure (`transfer::closure`): the share of a patch's hemisphere that the fronts of
//! surfaces cover, from rays. Every ray of every exposed patch of a closed room meets a
//! front (so the closure is exactly 1), also around a block standing off the patches'
//! grid; the receiving plate of two parallel plates admits the closed form `F = 0.19982`
//! within its binomial error, and not 1.

use crate::support::furnace_with_standing_block;
use std::path::Path;
use ugo::geometry::Mesh;
use ugo::scene::Scene;
use ugo::transfer::exposure::{Backs, measure_exposure};
use ugo::visibility::Visibility;

#[test]
fn every_exposed_patch_of_a_closed_room_closes_exactly() {
    let scene = furnace_with_standing_block(0.125);
    let mut mesh = Mesh::build(&scene.surfaces, 0.125);
    let visibility = Visibility::build(&mesh);
    measure_exposure(&mut mesh, &visibility, &ugo::progress::Silent);
    let backs = Backs::of(&mesh);
    let (mut rays, mut partly) = (0, 0);
    for p in mesh.patches.iter().filter(|p| p.exposed > 0.0) {
        let (closure, _) = backs.closure(&visibility, p);
        rays += closure.cast;
        partly += (p.exposed < p.area) as usize;
        assert!(closure.cast > 0 && closure.covered == closure.cast, "patch at {:?}: {closure:?}", p.centroid);
        assert!(closure.admits(1.0) && !closure.admits(0.99));
    }
    eprintln!("closed room: {rays} closure rays, all met a front ({partly} patches partly under the block)");
    assert!(partly > 0, "the block's foot print crosses patches");
}

#[test]
fn a_plate_facing_another_admits_its_closed_form_factor() {
    let scene = Scene::load(Path::new("cases/parallel-plates.toml")).unwrap();
    let mesh = Mesh::build(&scene.surfaces, 1.0);
    let visibility = Visibility::build(&mesh);
    let backs = Backs::of(&mesh);
    let receiver = mesh.patches.iter().find(|p| p.surface == 1).expect("the receiving plate");
    let (closure, _) = backs.closure(&visibility, receiver);
    eprintln!("parallel plates: {} of {} rays meet the other plate (F = 0.19982)", closure.covered, closure.cast);
    assert!(closure.admits(0.1998249) && !closure.admits(1.0), "{closure:?}");
}
