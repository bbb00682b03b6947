//! The sky model (`src/sky/`): the CIE distributions against their published values and
//! closed forms, the normalisation by integration, the sun's position.

mod components;
mod glazing;
mod labels;
mod maintenance;
mod office;
mod position;
mod sun_glass;
mod window;

use glam::DVec3;
use std::f64::consts::PI;
use ugo::sky::{Brightness, Distribution, Sky, SunPosition, relative_horizontal_illuminance};

/// The sun at altitude `h` and azimuth `a` (degrees), north towards −z.
pub fn sun(h: f64, a: f64) -> DVec3 {
    SunPosition { altitude_deg: h, azimuth_deg: a }.direction(DVec3::NEG_Z)
}

#[test]
fn the_traditional_overcast_sky_gives_seven_ninths_pi_of_its_zenith_luminance() {
    let ratio = relative_horizontal_illuminance(Distribution::Overcast, sun(60.0, 180.0));
    assert!((ratio / (7.0 * PI / 9.0) - 1.0).abs() < 1e-13, "{ratio}");
}

#[test]
fn the_uniform_sky_gives_pi_times_its_luminance() {
    for name in ["uniform", "5"] {
        let ratio = relative_horizontal_illuminance(Distribution::parse(name).unwrap(), sun(30.0, 90.0));
        assert!((ratio / PI - 1.0).abs() < 1e-13, "{name}: {ratio}");
    }
}

#[test]
fn general_skies_match_the_published_examples() {
    // colour-science's examples of CIE S 011 (Z = 45°, azimuth 180°; the sun at Z = 30°, azimuth 0°).
    let north = DVec3::NEG_Z;
    let element = SunPosition { altitude_deg: 45.0, azimuth_deg: 180.0 }.direction(north);
    let sun = SunPosition { altitude_deg: 60.0, azimuth_deg: 0.0 }.direction(north);
    for (t, expected) in [(1, 0.8325846), (12, 0.4544524)] {
        let got = Distribution::General(t).relative(element, sun);
        assert!((got - expected).abs() < 1e-7, "type {t}: {got}");
    }
}

#[test]
fn type_12_is_the_cie_clear_sky_formula() {
    let s = sun(35.0, 200.0);
    let zs = s.y.acos();
    let clear = |l: DVec3| {
        let (chi, z) = (l.dot(s).clamp(-1.0, 1.0).acos(), l.y.acos());
        (0.91 + 10.0 * (-3.0 * chi).exp() + 0.45 * chi.cos().powi(2)) * (1.0 - (-0.32 / z.cos()).exp())
    };
    let norm = (0.91 + 10.0 * (-3.0 * zs).exp() + 0.45 * zs.cos().powi(2)) * (1.0 - (-0.32f64).exp());
    for (h, a) in [(10.0, 0.0), (30.0, 190.0), (60.0, 90.0), (80.0, 300.0)] {
        let l = sun(h, a);
        let got = Distribution::parse("clear").unwrap().relative(l, s);
        // The standard's 1 + 10 (e^{-3χ} − e^{-3π/2}) is 0.9102 + 10 e^{-3χ}: 0.91 to 2e-4.
        assert!((got / (clear(l) / norm) - 1.0).abs() < 3e-4, "({h}, {a}): {got} against {}", clear(l) / norm);
    }
}

#[test]
fn horizontal_illuminance_agrees_with_a_brute_force_integral() {
    let s = sun(60.0, 180.0);
    for t in [1, 7, 12, 15] {
        let d = Distribution::General(t);
        let (n, m) = (600, 1200);
        let mut brute = 0.0;
        for i in 0..n {
            let h = (i as f64 + 0.5) / n as f64 * PI / 2.0;
            for j in 0..m {
                let a = (j as f64 + 0.5) / m as f64 * 2.0 * PI;
                let l = DVec3::new(h.cos() * a.cos(), h.sin(), h.cos() * a.sin());
                brute += d.relative(l, s) * h.sin() * h.cos() * (PI / 2.0 / n as f64) * (2.0 * PI / m as f64);
            }
        }
        let ratio = relative_horizontal_illuminance(d, s);
        assert!((ratio / brute - 1.0).abs() < 2e-4, "type {t}: {ratio} against {brute}");
    }
}

#[test]
fn a_sky_given_by_its_horizontal_illuminance_has_the_matching_zenith_luminance() {
    let s = sun(60.0, 180.0);
    let by_e = Sky::new(Distribution::Overcast, s, Brightness::Horizontal(10_000.0), 0.2, 0.0);
    assert!((by_e.zenith_luminance / (10_000.0 * 9.0 / (7.0 * PI)) - 1.0).abs() < 1e-12);
    let by_l = Sky::new(Distribution::Overcast, s, Brightness::Zenith(by_e.zenith_luminance), 0.2, 0.0);
    assert!((by_l.horizontal_illuminance / 10_000.0 - 1.0).abs() < 1e-12);
    assert!((by_e.luminance(DVec3::NEG_Y) - 0.2 * 10_000.0 / PI).abs() < 1e-9, "the ground");
    assert!((by_e.luminance(DVec3::Y) - by_e.zenith_luminance).abs() < 1e-9, "the zenith");
}
