//! A probe's luminance on a glossy floor against a fine quadrature of the reflection
//! integral `L(q, l) = (1/π) ∫ ρ(l, l') Le cosθ' dω'` over a lamp above it. The field holds
//! one direction cell: only the material's own luminance factor at the probe (the final
//! gather of `readout::glossy`) can show the lamp's highlight; the cell-averaged factor
//! spreads it over the hemisphere. At the highlight's edge (p3) the lamp's 0.1 m patches
//! must be cut where the lobe varies over them: with their four points alone it read 3.7 %
//! low.

use super::readings;
use crate::support::over_parallelogram;
use glam::DVec3;
use std::path::Path;
use ugo::geometry::{Frame, Mesh};
use ugo::material::MaterialModel;
use ugo::scene::Scene;
use ugo::trace::{TraceOptions, World, trace_probes};

const FLOOR: MaterialModel = MaterialModel::Phong { diffuse: 0.1, specular: 0.8, exponent: 100.0 };
const LAMP: f64 = 1000.0;

/// `(1/π) ∫ ρ(n, l') LAMP cosθ' dω'` at `q` on the floor (normal +y), seen along the
/// normal, over the 0.4 m lamp facing down at y = 1 centred above the origin.
fn quadrature(q: DVec3) -> f64 {
    let frame = Frame::around(DVec3::Y);
    let l = frame.local(DVec3::Y);
    let reflected = |w: DVec3, solid_angle: f64| FLOOR.luminance_factor(l, frame.local(w)) * w.y * solid_angle;
    let (o, u, v) = (DVec3::new(-0.2, 1.0, -0.2), DVec3::new(0.4, 0.0, 0.0), DVec3::new(0.0, 0.0, 0.4));
    LAMP * over_parallelogram(o, u, v, q, 400, reflected) / std::f64::consts::PI
}

/// The case: the glossy floor (2 × 2 m, patches of 0.1 m) under the black lamp, with point
/// probes at `(position, normal)`.
fn lamp_over_glossy_floor(probes: &[([f64; 3], [f64; 3])]) -> String {
    let mut text = String::from(
        "[discretization]\npatch_size = 0.1\n\
         [[material]]\nname = \"glossy\"\ntype = \"phong\"\nreflectance = 0.1\nspecular = 0.8\nexponent = 100\n\
         [[material]]\nname = \"black\"\ntype = \"lambert\"\nreflectance = 0\n\
         [[surface]]\nname = \"floor\"\nshape = \"rectangle\"\nmaterial = \"glossy\"\n\
         origin = [-1, 0, -1]\nedge_u = [0, 0, 2]\nedge_v = [2, 0, 0]\n\
         [[surface]]\nname = \"lamp\"\nshape = \"rectangle\"\nmaterial = \"black\"\n\
         origin = [-0.2, 1, -0.2]\nedge_u = [0.4, 0, 0]\nedge_v = [0, 0, 0.4]\nemission = { luminance = 1000 }\n",
    );
    for (i, (p, n)) in probes.iter().enumerate() {
        text += &format!("[[probe]]\nname = \"p{i}\"\nposition = {p:?}\nnormal = {n:?}\n");
    }
    text
}

#[test]
fn a_probe_on_a_glossy_floor_reads_the_lamps_highlight_by_the_materials_own_factor() {
    let probes = [[0.0, 0.0], [0.1, 0.0], [0.15, 0.1], [0.3, 0.3]].map(|[x, z]| ([x, 0.0, z], [0.0, 1.0, 0.0]));
    for (reading, (p, _)) in readings(&lamp_over_glossy_floor(&probes)).iter().zip(probes) {
        let exact = quadrature(DVec3::from_array(p));
        let error = reading.luminance / exact - 1.0;
        eprintln!("{}: {:.3} cd/m², quadrature {exact:.3} ({:+.3} %)", reading.name, reading.luminance, 100.0 * error);
        assert!(error.abs() < 0.005, "{}: {} against {exact}", reading.name, reading.luminance);
    }
}

#[test]
fn a_probe_beside_the_lamp_receives_its_image_in_the_glossy_floor() {
    // Facing down at the lamp's height, 0.3 m beside it: all its light is the floor's
    // reflection of the lamp, which the floor's single direction cell cannot hold.
    let probes = [([0.5, 1.0, 0.0], [0.0, -1.0, 0.0]), ([0.45, 1.0, 0.2], [0.0, -1.0, 0.0])];
    for (reading, (p, _)) in readings(&lamp_over_glossy_floor(&probes)).iter().zip(probes) {
        let exact = image_illuminance(DVec3::from_array(p), 200, 24);
        let error = reading.illuminance / exact - 1.0;
        eprintln!("{}: {:.4} lx, quadrature {exact:.4} ({:+.3} %)", reading.name, reading.illuminance, 100.0 * error);
        assert!(error.abs() < 0.01, "{}: {} against {exact}", reading.name, reading.illuminance);
    }
}

/// The illuminance at `p` (receiver facing down) from the lamp's image in the floor:
/// `∫_floor L(x → p) cosθ_p cosθ_x / r² dA`, `L(x → p)` the floor's reflection of the lamp,
/// both integrals by the midpoint rule (`m × m` over the floor, `n × n` over the lamp).
fn image_illuminance(p: DVec3, m: usize, n: usize) -> f64 {
    let frame = Frame::around(DVec3::Y);
    let (o, u, v) = (DVec3::new(-1.0, 0.0, -1.0), DVec3::new(2.0, 0.0, 0.0), DVec3::new(0.0, 0.0, 2.0));
    let lamp = (DVec3::new(-0.2, 1.0, -0.2), DVec3::new(0.4, 0.0, 0.0), DVec3::new(0.0, 0.0, 0.4));
    let mut e = 0.0;
    for i in 0..m {
        for j in 0..m {
            let x = o + u * ((i as f64 + 0.5) / m as f64) + v * ((j as f64 + 0.5) / m as f64);
            let to_p = (p - x).normalize();
            let l = frame.local(to_p);
            let reflected = |w: DVec3, solid_angle: f64| FLOOR.luminance_factor(l, frame.local(w)) * w.y * solid_angle;
            let luminance = LAMP * over_parallelogram(lamp.0, lamp.1, lamp.2, x, n, reflected) / std::f64::consts::PI;
            e += luminance * to_p.y * to_p.y / (p - x).length_squared() * 4.0 / (m * m) as f64;
        }
    }
    e
}

#[test]
fn a_glossy_floor_under_a_panel_lit_by_its_image_reads_as_traced() {
    // A white panel beside the lamp takes nearly all its light from the lamp's image in the
    // floor. The field's one direction cell spreads the floor's reflection over the
    // hemisphere, so the panel's stored luminance is wrong; the floor under it, whose lobe
    // sees the panel, reads it right only where the panel's points are gathered again
    // (`readout::luminance`, relit).
    let panel = "[[material]]\nname = \"white\"\ntype = \"lambert\"\nreflectance = 0.8\n\
                 [[surface]]\nname = \"panel\"\nshape = \"rectangle\"\nmaterial = \"white\"\n\
                 origin = [0.3, 1, -0.5]\nedge_u = [0.7, 0, 0]\nedge_v = [0, 0, 1]\n";
    let probes = [([0.65, 0.0, 0.0], [0.0, 1.0, 0.0]), ([0.8, 0.0, 0.3], [0.0, 1.0, 0.0])];
    let text = lamp_over_glossy_floor(&probes) + panel;
    let scene = Scene::parse(Path::new("cases/test.toml"), text.clone()).unwrap_or_else(|e| panic!("{e}"));
    let world = World::new(&scene, Mesh::build(&scene.surfaces, scene.discretization.patch_size));
    let traced = trace_probes(&world, &scene.probes, 1 << 21, &TraceOptions::default(), &|_| {});
    for (reading, estimate) in readings(&text).iter().zip(&traced) {
        let (value, sigma) = estimate.luminance;
        let error = reading.luminance / value - 1.0;
        eprintln!(
            "{}: {:.4} cd/m², traced {value:.4} ± {sigma:.4} ({:+.3} %)",
            reading.name,
            reading.luminance,
            100.0 * error
        );
        assert!((reading.luminance - value).abs() < 0.01 * value + 3.0 * sigma, "{}: {error}", reading.name);
    }
}
