//! Cylindrical and semi-cylindrical illuminance against their closed forms: `π L` in a
//! uniform enclosure, and for a point source of intensity `I` at `d` (`θ` from the axis,
//! `ψ` the azimuth from the facing direction) `E_z = I sinθ/(π d²)`,
//! `E_sc = I sinθ (1 + cos ψ)/(π d²)`.

use super::{readings, room};
use std::f64::consts::PI;

fn probe(name: &str, kind: &str, position: [f64; 3], keys: &str) -> String {
    format!("[[probe]]\nname = \"{name}\"\nkind = \"{kind}\"\nposition = {position:?}\n{keys}\n")
}

#[test]
fn a_uniform_enclosure_gives_pi_l_on_cylinders_and_half_cylinders() {
    let mut text = room(2.0, 0.5, 1.0);
    text += &probe("z", "cylindrical", [1.0, 0.9, 1.1], "");
    text += &probe("tilted", "cylindrical", [0.8, 1.2, 1.0], "axis = [1, 1, 0]");
    text += &probe("sc", "semi_cylindrical", [1.0, 0.9, 1.1], "direction = [1, 0.3, 0]");
    for r in readings(&text) {
        assert!((r.illuminance - 2.0 * PI).abs() < 1e-6, "{r:?}");
        assert!(r.luminance.is_nan() && r.direct == 0.0, "{r:?}");
    }
}

#[test]
fn a_point_source_gives_the_closed_form_exactly() {
    let mut text = room(4.0, 0.0, 0.0);
    text += "[[luminaire]]\nname = \"bulb\"\ntype = \"isotropic\"\nintensity = 100\nposition = [2.5, 3.0, 1.5]\n";
    let p = [1.5, 1.2, 2.0];
    text += &probe("z", "cylindrical", p, "");
    text += &probe("towards", "semi_cylindrical", p, "direction = [1, 0, 0]");
    text += &probe("away", "semi_cylindrical", p, "direction = [-1, 0.5, 0]");
    text += &probe("sideways", "cylindrical", p, "axis = [0, 0, 1]");
    let r = readings(&text);
    let (dx, dy, dz) = (1.0f64, 1.8f64, -0.5f64);
    let d3 = (dx * dx + dy * dy + dz * dz).powf(1.5);
    let across = (dx * dx + dz * dz).sqrt();
    let expected = [
        100.0 * across / (PI * d3),
        100.0 * (across + dx) / (PI * d3),
        100.0 * (across - dx) / (PI * d3),
        100.0 * (dx * dx + dy * dy).sqrt() / (PI * d3),
    ];
    for (r, e) in r.iter().zip(expected) {
        assert!((r.illuminance - e).abs() < 1e-12 * e, "{r:?}: closed form {e}");
        assert_eq!(r.direct, r.illuminance, "a black room reflects nothing");
    }
}
