//! Openings hidden behind a wall: on the building floor (`cases/building.toml`, 28 rooms,
//! 29 windows), every opening that an occluder hides from a point lets no ray from the point
//! through it out, and the light through every opening is the same whether hidden ones are
//! known or traced.

use glam::DVec3;
use std::path::Path;
use ugo::geometry::{ConvexPolygon, Mesh};
use ugo::luminaire::LuminaireKind;
use ugo::scene::Scene;
use ugo::sky::{Opening, READING, Sky, through_window};
use ugo::visibility::{Sight, SightFrom, Visibility};

fn building() -> (Scene, Mesh, Vec<(Opening, Sky)>) {
    let scene = Scene::load(Path::new("cases/building.toml")).unwrap();
    let mesh = Mesh::build(&scene.surfaces, 1.0);
    let windows = scene
        .luminaires
        .iter()
        .filter_map(|l| match &l.kind {
            LuminaireKind::Window { window, sky } => Some((*window, sky.clone())),
            _ => None,
        })
        .collect();
    (scene, mesh, windows)
}

/// True when none of 100 rays from `x` through a grid over the parallelogram `window` (or
/// triangle, its first three corners) leaves the scene.
fn every_ray_blocked(v: &Visibility, x: DVec3, face: u32, window: &ConvexPolygon) -> bool {
    let [a, b, d] = [0, 1, window.vertices().len() - 1].map(|i| window.vertices()[i]);
    (0..100).all(|k| {
        let (s, t) = (((k % 10) as f64 + 0.5) / 10.0, ((k / 10) as f64 + 0.5) / 10.0);
        !v.escapes(x, a + s * (b - a) + t * (d - a) - x, face)
    })
}

#[test]
fn an_opening_an_occluder_hides_lets_no_ray_out() {
    let (scene, mesh, windows) = building();
    let v = Visibility::build_for(&scene.surfaces, &mesh);
    let (mut pairs, mut hidden, mut pieces) = (0, 0, 0);
    for p in mesh.patches.iter().step_by(37) {
        let x = p.centroid + 1e-3 * p.normal;
        for (opening, _) in &windows {
            let window = &opening.polygon;
            if window.vertices().iter().all(|w| (*w - x).dot(p.normal) <= 0.0) {
                continue;
            }
            pairs += 1;
            let sight = SightFrom::new(&v, x, p.normal, p.face);
            for (k, piece) in std::iter::once(*window).chain(window.split()).enumerate() {
                if sight.hidden(&piece, &mut 0) {
                    assert!(every_ray_blocked(&v, x, p.face, &piece), "piece {k} of an opening from {x} got out");
                    hidden += usize::from(k == 0);
                    pieces += 1;
                }
            }
        }
    }
    eprintln!("{hidden} of {pairs} openings facing a point hidden, {pieces} wholes and quarters");
    assert!(hidden > pairs / 2, "most openings lie behind walls: {hidden} of {pairs} found");
}

#[test]
fn the_light_through_an_opening_is_the_same_with_its_occluders_known() {
    let (scene, mesh, windows) = building();
    let with = Visibility::build_for(&scene.surfaces, &mesh);
    let without = Visibility::build(&mesh);
    let (mut rays_with, mut rays_without, mut lit) = (0, 0, 0);
    for p in mesh.patches.iter().step_by(97) {
        let x = p.centroid + 1e-3 * p.normal;
        for (opening, sky) in &windows {
            let light = |v: &Visibility, rays: &mut usize| {
                let mut e = 0.0;
                let sight = SightFrom::new(v, x, p.normal, p.face);
                *rays += through_window(READING.eta, sky, opening, x, p.normal, &sight, 0.0, &mut |_, de, _| e += de);
                e
            };
            let (a, b) = (light(&with, &mut rays_with), light(&without, &mut rays_without));
            assert!((a - b).abs() <= 1e-9 * b.abs().max(1.0), "{a} lx against {b} lx at {x}");
            lit += usize::from(b > 0.0);
        }
    }
    eprintln!("{lit} lit pairs; rays {rays_with} with the occluders, {rays_without} without");
    assert!(lit > 10 && 5 * rays_with < 4 * rays_without, "{lit} lit; {rays_with} rays against {rays_without}");
}
