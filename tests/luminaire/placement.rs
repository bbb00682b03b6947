//! Where a luminaire points: its frame from the aim and rotation, and the scale from its
//! multiplier and its file's tilt factor.

use super::{point, table};
use glam::DVec3;
use std::f64::consts::PI;
use ugo::luminaire::LuminaireKind;
use ugo::luminaire::{Source, frame};

#[test]
fn a_downlight_frame_has_c0_along_x_and_c90_counter_clockwise_seen_from_above() {
    let f = frame(DVec3::NEG_Y, 0.0);
    assert!((f.tangent - DVec3::X).length() < 1e-15, "C0 = x: {f:?}");
    assert!((f.bitangent - DVec3::NEG_Z).length() < 1e-15, "C90 = −z: {f:?}");
    assert!((f.normal - DVec3::Y).length() < 1e-15);
    let turned = frame(DVec3::NEG_Y, 90.0);
    assert!((turned.tangent - DVec3::NEG_Z).length() < 1e-15, "rotate_deg turns C0 towards C90: {turned:?}");
}

#[test]
fn every_aim_gives_a_right_handed_frame_with_up_opposite_the_aim() {
    for aim in [DVec3::X, DVec3::NEG_X, DVec3::new(0.3, -0.2, 0.9), DVec3::Z, DVec3::Y, DVec3::new(1.0, -1.0, 0.0)] {
        let aim = aim.normalize();
        for rotate in [0.0, 37.0, -120.0] {
            let f = frame(aim, rotate);
            assert!((f.normal + aim).length() < 1e-12);
            assert!((f.tangent.cross(f.bitangent) - f.normal).length() < 1e-12, "{aim} {rotate}: {f:?}");
            assert!(f.tangent.dot(f.normal).abs() < 1e-12 && (f.tangent.length() - 1.0).abs() < 1e-12);
        }
    }
}

#[test]
fn rotating_a_luminaire_turns_its_distribution_about_the_aim() {
    let mut lamp = point("lamp", DVec3::ZERO, DVec3::NEG_Y, table("c-full-2019.ies"));
    let still = Source::of(&lamp);
    let LuminaireKind::Point(p) = &mut lamp.kind else { unreachable!() };
    p.rotate_deg = 90.0;
    let turned = Source::of(&lamp);
    let about_up = |w: DVec3, deg: f64| glam::DMat3::from_rotation_y(deg.to_radians()) * w;
    for w in [DVec3::new(0.5, -0.8, 0.1), DVec3::new(-0.2, -0.7, -0.6), DVec3::new(0.9, -0.3, 0.2)] {
        let w = w.normalize();
        let (a, b) = (turned.intensity(about_up(w, 90.0)), still.intensity(w));
        assert!((a - b).abs() < 1e-9 * b, "{w}: {a} vs {b}");
    }
    assert!(
        (still.intensity(DVec3::new(0.5, -0.5, 0.0).normalize())
            - still.intensity(DVec3::new(-0.5, -0.5, 0.0).normalize()))
        .abs()
            > 1.0,
        "the test distribution is asymmetric"
    );
}

#[test]
fn the_multiplier_and_the_tilt_factor_scale_the_flux() {
    let mut lamp = point("lamp", DVec3::ZERO, DVec3::NEG_Y, table("c-isotropic-tilt-2002.ies"));
    let nominal = 4.0 * PI * 1000.0;
    assert!((Source::of(&lamp).flux().unwrap() / nominal - 1.0).abs() < 1e-12, "aimed down: tilt 0°, factor 1");
    let aimed = |lamp: &mut ugo::luminaire::Luminaire, aim: DVec3| {
        let LuminaireKind::Point(p) = &mut lamp.kind else { unreachable!() };
        p.aim = aim.normalize();
        p.multiplier = 0.5;
        Source::of(lamp).flux().unwrap()
    };
    let tilted = aimed(&mut lamp, DVec3::new(1.0, -1.0, 0.0));
    assert!((tilted / (nominal * 0.5 * 0.8) - 1.0).abs() < 1e-12, "tilted 45°: factor 0.8, times 0.5: {tilted}");
    let horizontal = aimed(&mut lamp, DVec3::X);
    assert!((horizontal / (nominal * 0.5 * 0.5) - 1.0).abs() < 1e-12, "horizontal: 0.5");
}
