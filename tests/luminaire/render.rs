//! Rendering a luminaire-lit scene: the final gather adds the luminaires' direct light
//! exactly at each visible point, so a lit floor shows `ρ E(q)/π` pixel by pixel (to the
//! f32 precision of the hit points).

use super::point;
use crate::support::{build, lambert, rectangle, scene, solve, surface};
use glam::DVec3;
use std::f64::consts::PI;
use ugo::directions::DirectionSet;
use ugo::photometry::Distribution;
use ugo::render::{LitScene, Projection, Shading, render};
use ugo::scene::Camera;

#[test]
fn the_final_gather_shows_a_luminaire_lit_floor_exactly() {
    let floor = rectangle([-1.0, 0.0, -1.0], [0.0, 0.0, 2.0], [2.0, 0.0, 0.0]);
    let mut s = scene(vec![lambert("grey", 0.5)], vec![surface("floor", floor, 0, false, None)], 0.5);
    let lamp = DVec3::new(0.2, 1.0, -0.1);
    s.luminaires.push(point("lamp", lamp, DVec3::NEG_Y, Distribution::Lambertian { peak: 1000.0 }));
    let model = build(&s);
    let x = solve(&model);
    let materials = s.materials.iter().map(|m| m.model.clone()).collect();
    let sources = model.sources.clone();
    let mut lit = LitScene::new(model.mesh, DirectionSet::single(), x, materials).with_luminaires(sources);
    let camera = Camera {
        name: "down".into(),
        position: DVec3::new(0.0, 0.8, 0.0),
        look_at: DVec3::ZERO,
        up: DVec3::Z,
        fov_deg: 70.0,
        resolution: [16, 16],
        samples: 1,
    };
    let view = Projection::of(&camera);
    let exact = |q: DVec3| {
        let r = q - lamp;
        let cos = -r.y / r.length();
        0.5 * 1000.0 * cos * cos / r.length_squared() / PI
    };
    let mut worst_flat: f64 = 0.0;
    for shading in [Shading::Flat, Shading::Gather { rays: 4 }] {
        lit.set_shading(shading);
        let image = render(&lit, &camera);
        for py in 0..16 {
            for px in 0..16 {
                let d = view.sample(px, py, 0);
                let q = view.eye + d * (-view.eye.y / d.y);
                let error = image.luminance[py * 16 + px] / exact(q) - 1.0;
                match shading {
                    Shading::Flat => worst_flat = worst_flat.max(error.abs()),
                    _ => assert!(error.abs() < 1e-6, "pixel ({px}, {py}) at {q}: {error:+e}"),
                }
            }
        }
    }
    assert!(worst_flat > 1e-2, "flat shading shows the patch means: {worst_flat}");
}
