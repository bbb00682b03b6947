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
use ugo::geometry::Frame;
use ugo::material::MaterialModel;

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

#[test]
fn a_probe_on_a_glossy_floor_reads_the_lamps_highlight_by_the_materials_own_factor() {
    let probes = [[0.0, 0.0], [0.1, 0.0], [0.15, 0.1], [0.3, 0.3]];
    let mut text = String::from(
        "[discretization]\npatch_size = 0.1\n\
         [[material]]\nname = \"glossy\"\ntype = \"phong\"\nreflectance = 0.1\nspecular = 0.8\nexponent = 100\n\
         [[material]]\nname = \"black\"\ntype = \"lambert\"\nreflectance = 0\n\
         [[surface]]\nname = \"floor\"\nshape = \"rectangle\"\nmaterial = \"glossy\"\n\
         origin = [-1, 0, -1]\nedge_u = [0, 0, 2]\nedge_v = [2, 0, 0]\n\
         [[surface]]\nname = \"lamp\"\nshape = \"rectangle\"\nmaterial = \"black\"\n\
         origin = [-0.2, 1, -0.2]\nedge_u = [0.4, 0, 0]\nedge_v = [0, 0, 0.4]\nemission = { luminance = 1000 }\n",
    );
    for (i, [x, z]) in probes.iter().enumerate() {
        text += &format!("[[probe]]\nname = \"p{i}\"\nposition = [{x}, 0, {z}]\nnormal = [0, 1, 0]\n");
    }
    let readings = readings(&text);
    for (reading, [x, z]) in readings.iter().zip(probes) {
        let exact = quadrature(DVec3::new(x, 0.0, z));
        let error = reading.luminance / exact - 1.0;
        eprintln!("{}: {:.3} cd/m², quadrature {exact:.3} ({:+.3} %)", reading.name, reading.luminance, 100.0 * error);
        assert!(error.abs() < 0.005, "{}: {} against {exact}", reading.name, reading.luminance);
    }
}
