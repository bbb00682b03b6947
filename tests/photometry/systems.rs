//! The goniometric systems: angles and directions are inverse to each other, type B obeys
//! the usual B-to-C relations, and files of types A, B and C point their light where the
//! documented luminaire frame says (`x` = C0, `y` = C90, aim `−z`).

use super::read;
use glam::DVec3;
use ugo::photometry::{Distribution, System};

fn unit(x: f64, y: f64, z: f64) -> DVec3 {
    DVec3::new(x, y, z).normalize()
}

#[test]
fn angles_invert_directions_in_every_system() {
    for system in [System::A, System::B, System::C] {
        for (a, theta) in [(0.0, 10.0), (37.0, 80.0), (-120.0, 135.0), (179.0, 45.0)] {
            let (a2, t2) = system.angles(system.direction(a, theta));
            assert!((a2 - a).abs() < 1e-9 && (t2 - theta).abs() < 1e-9, "{system:?}: ({a}, {theta}) → ({a2}, {t2})");
        }
    }
}

#[test]
fn type_b_angles_follow_the_b_to_c_relations() {
    for (c, gamma) in [(20.0f64, 30.0f64), (75.0, 60.0), (110.0, 40.0)] {
        let (h, theta) = System::B.angles(System::C.direction(c, gamma));
        let v = 90.0 - theta;
        let (c, gamma, h, v) = (c.to_radians(), gamma.to_radians(), h.to_radians(), v.to_radians());
        assert!((h.tan() - c.cos() * gamma.tan()).abs() < 1e-12, "tan H = cos C tan γ");
        assert!((v.sin() - c.sin() * gamma.sin()).abs() < 1e-12, "sin V = sin C sin γ");
    }
}

#[test]
fn lambertian_files_of_types_a_and_b_shine_about_the_aim() {
    for name in ["b-lateral-2002.ies", "a-front-2002.ies"] {
        let d = Distribution::Table(Box::new(read(name)));
        for l in [unit(0.0, 0.0, -1.0), unit(0.3, -0.5, -0.8), unit(-0.7, 0.2, -0.4), unit(0.1, 0.9, -0.2)] {
            let exact = 1000.0 * -l.z;
            assert!((d.intensity(l) / exact - 1.0).abs() < 1e-2, "{name} towards {l}: {} vs {exact}", d.intensity(l));
        }
        assert_eq!(d.intensity(unit(0.2, 0.3, 0.5)), 0.0, "{name}: nothing behind the luminaire");
    }
}

#[test]
fn positive_angles_point_the_documented_way() {
    let (s, c) = 40f64.to_radians().sin_cos();
    let b = Distribution::Table(Box::new(read("b-front-2002.ies")));
    let towards_x = b.intensity(DVec3::new(s, 0.0, -c));
    let towards_minus_x = b.intensity(DVec3::new(-s, 0.0, -c));
    assert!((towards_x / (1000.0 * c * (1.0 + 0.4 * s)) - 1.0).abs() < 1e-3, "type B: H > 0 towards +x: {towards_x}");
    assert!((towards_minus_x / (1000.0 * c * (1.0 - 0.4 * s)) - 1.0).abs() < 1e-3, "{towards_minus_x}");

    let c90 = Distribution::Table(Box::new(read("c-bilateral-90-270-1995.ies")));
    let (s30, c30) = 30f64.to_radians().sin_cos();
    let towards_y = c90.intensity(DVec3::new(0.0, s30, -c30));
    assert!((towards_y / (1000.0 * c30 * 1.5) - 1.0).abs() < 1e-4, "type C: C90 is +y: {towards_y}");
}
