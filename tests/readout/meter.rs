//! The luminance meter reads the mean luminance in its cone: `L` exactly in a uniform
//! enclosure at any field of view, and in a scene whose luminance changes across a plane
//! through its axis exactly the mean of the two sides.

use super::{readings, room};

fn meter(name: &str, position: [f64; 3], direction: [f64; 3], fov_deg: f64) -> String {
    format!(
        "[[probe]]\nname = \"{name}\"\nkind = \"luminance_meter\"\nposition = {position:?}\ndirection = {direction:?}\nfov_deg = {fov_deg}\n"
    )
}

#[test]
fn a_meter_in_a_uniform_enclosure_reads_its_luminance_at_any_field_of_view() {
    // L = L_e / (1 − ρ) = 1 / 0.5 everywhere.
    let mut text = room(2.0, 0.5, 1.0);
    for (i, fov) in [1.0, 30.0, 120.0, 180.0].iter().enumerate() {
        text += &meter(&format!("m{i}"), [1.0, 0.9, 1.1], [0.3, -1.0, 0.2], *fov);
    }
    for r in readings(&text) {
        assert!((r.luminance - 2.0).abs() < 1e-6, "{r:?}");
        // The receiver facing the view sees the uniform enclosure's π L.
        assert!((r.illuminance - 2.0 * std::f64::consts::PI).abs() < 1e-6, "{r:?}");
        assert_eq!(r.kind.name(), "luminance_meter");
    }
}

#[test]
fn a_meter_across_a_change_of_luminance_reads_the_mean_of_the_two_sides() {
    // A black room whose back wall is covered by two emitters, 100 cd/m² for x < 2 and
    // 300 cd/m² beyond, just in front of it.
    let mut text = room(4.0, 0.0, 0.0);
    for (name, x, luminance) in [("left", 0.0, 100.0), ("right", 2.0, 300.0)] {
        text += &format!(
            "[[surface]]\nname = \"{name}\"\nshape = \"rectangle\"\nmaterial = \"grey\"\norigin = [{x}, 0, 0.01]\n\
             edge_u = [2, 0, 0]\nedge_v = [0, 4, 0]\nemission = {{ luminance = {luminance} }}\n"
        );
    }
    text += &meter("across", [2.0, 2.0, 3.0], [0.0, 0.0, -1.0], 40.0);
    text += &meter("tilted", [2.0, 2.0, 3.0], [0.0, -0.5, -2.99], 20.0);
    text += &meter("left", [1.0, 2.0, 3.0], [0.0, 0.0, -1.0], 20.0);
    let r = readings(&text);
    assert!((r[0].luminance - 200.0).abs() < 1e-9, "{:?}", r[0]);
    assert!((r[1].luminance - 200.0).abs() < 1e-9, "{:?}", r[1]);
    assert!((r[2].luminance - 100.0).abs() < 1e-9, "{:?}", r[2]);
}
