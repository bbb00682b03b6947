//! The final gather on a glossy floor against a fine quadrature of the reflection integral
//! `L(q, l) = (1/π) ∫ ρ(l, l') L(l') cosθ' dω'`: a lamp's highlight (the direct part) and
//! a bright wall seen in the floor (the indirect part, sampled from the material's lobe).
//! The field is stored in one direction cell: only the material's own luminance factor at
//! `q` can make the highlight (a cell-averaged factor would spread it over the hemisphere).
//! The wall's bound holds only for well-stratified directions: with the Latin hypercube
//! the gather used before (second coordinate `7r + shift mod n`), 4,096 rays scattered by
//! ±0.8 % from seed to seed, with the shifted Hammersley set by ±0.02 %.

use crate::support::{material, over_parallelogram, rectangle, scene, surface};
use glam::DVec3;
use ugo::directions::DirectionSet;
use ugo::geometry::{Emission, Frame, Mesh, Shape};
use ugo::material::MaterialModel;
use ugo::random::Rng;
use ugo::render::{LitScene, Shading};

/// Phong, all specular, a lobe about 7° wide at half maximum.
const FLOOR: MaterialModel = MaterialModel::Phong { diffuse: 0.0, specular: 0.9, exponent: 100.0 };
const LAMP: f64 = 1000.0;
const WALL: f64 = 100.0;

/// A 2 × 2 m glossy floor facing +y with `other` above it (black), meshed at `patch_size`.
fn floor_under(other: Shape, emission: Option<Emission>, patch_size: f64) -> LitScene {
    let floor = rectangle([-1.0, 0.0, -1.0], [0.0, 0.0, 2.0], [2.0, 0.0, 0.0]);
    let emits = emission.is_some();
    let black = MaterialModel::Lambert { reflectance: 0.0, transmittance: 0.0 };
    let s = scene(
        vec![material("glossy", FLOOR), material("black", black)],
        vec![surface("floor", floor, 0, false, None), surface("other", other, 1, false, emission)],
        patch_size,
    );
    let mesh = Mesh::build(&s.surfaces, patch_size);
    let luminance = if emits {
        mesh.emission.clone()
    } else {
        mesh.patches.iter().map(|p| if p.surface == 1 { WALL } else { 0.0 }).collect()
    };
    let materials = s.materials.iter().map(|m| m.model.clone()).collect();
    LitScene::new(mesh, DirectionSet::single(), luminance, materials)
}

/// `(1/π) ∫ ρ(l, l') L cosθ' dω'` at `q` on the floor over the rectangle `origin + s·u + t·v`
/// of uniform luminance `l_source` facing `q`, by the midpoint rule on `n × n` pieces.
fn quadrature(q: DVec3, eye: DVec3, origin: DVec3, u: DVec3, v: DVec3, l_source: f64, n: usize) -> f64 {
    let frame = Frame::around(DVec3::Y);
    let l = frame.local((eye - q).normalize());
    let reflected = |w: DVec3, solid_angle: f64| FLOOR.luminance_factor(l, frame.local(w)) * w.y * solid_angle;
    l_source * over_parallelogram(origin, u, v, q, n, reflected) / std::f64::consts::PI
}

fn gathered(lit: &mut LitScene, eye: DVec3, q: DVec3, rays: usize) -> f64 {
    lit.set_shading(Shading::Gather { rays });
    lit.luminance_along(eye, (q - eye).normalize(), rays, &mut Rng::keyed(7))
}

/// Prints and checks `got` within the relative `bound` of `exact`.
fn expect_within(what: &str, got: f64, exact: f64, bound: f64) {
    let error = got / exact - 1.0;
    eprintln!("{what}: gathered {got:.3} cd/m², quadrature {exact:.3} ({:+.3} %)", 100.0 * error);
    assert!(error.abs() < bound, "{what}: {got} against {exact}");
}

#[test]
fn the_gather_shows_a_lamps_glossy_highlight_as_the_material_makes_it() {
    // A 0.4 m lamp 1 m above the floor, facing down; the eye sees its mirror image at q = 0.
    let (origin, u, v) = (DVec3::new(0.3, 1.0, -0.2), DVec3::new(0.4, 0.0, 0.0), DVec3::new(0.0, 0.0, 0.4));
    let lamp = rectangle(origin.to_array(), u.to_array(), v.to_array());
    let mut lit = floor_under(lamp, Some(Emission::Luminance(LAMP)), 0.05);
    let eye = DVec3::new(-0.5, 1.0, 0.0);
    let mut peak = 0.0;
    for q in [DVec3::ZERO, DVec3::new(-0.08, 0.0, 0.0), DVec3::new(0.0, 0.0, 0.09), DVec3::new(0.1, 0.0, 0.1)] {
        let exact = quadrature(q, eye, origin, u, v, LAMP, 400);
        expect_within(&format!("highlight at {q}"), gathered(&mut lit, eye, q, 1), exact, 0.005);
        peak = f64::max(peak, exact);
    }
    assert!(peak > 0.3 * LAMP, "the lamp is seen in the floor: {peak}");
    let aside = quadrature(DVec3::new(-0.3, 0.0, 0.3), eye, origin, u, v, LAMP, 100);
    assert!(aside < 0.01 * peak, "the highlight is sharp: {aside} beside {peak}");
}

#[test]
fn the_gather_shows_a_bright_wall_in_a_glossy_floor_through_the_materials_lobe() {
    // A 1 m high wall at x = 0.6 facing −x, of stored (not emitted) luminance WALL.
    let (origin, u, v) = (DVec3::new(0.6, 0.0, -1.0), DVec3::new(0.0, 0.0, 2.0), DVec3::new(0.0, 1.0, 0.0));
    let wall = rectangle(origin.to_array(), u.to_array(), v.to_array());
    let mut lit = floor_under(wall, None, 0.25);
    let eye = DVec3::new(-0.6, 0.5, 0.0);
    for q in [DVec3::new(0.0, 0.0, 0.0), DVec3::new(0.3, 0.0, 0.2)] {
        let exact = quadrature(q, eye, origin, u, v, WALL, 800);
        expect_within(&format!("wall in the floor at {q}"), gathered(&mut lit, eye, q, 4096), exact, 0.002);
    }
}
