//! Glazing (`ugo::sky::Glazing`): the Fresnel model of one and two panes against its closed
//! forms. A lossless pane transmits `(1 − r)/(1 + r)` per polarisation, `2n/(n² + 1)` at
//! normal incidence; the normal transmittance asked for is met exactly; nothing passes at
//! grazing incidence; two lossless panes transmit `(1 − r)/(1 + 3r)` per polarisation; and a
//! glazed opening under a uniform sky gives `π L ∫ τ(θ) cos θ dω / π` (a brute-force sum).

use super::sun;
use glam::DVec3;
use ugo::geometry::ConvexPolygon;
use ugo::sky::{Brightness, Component, Distribution, Glazing, Opening, Sky, through_window};

#[test]
fn a_lossless_pane_transmits_the_fresnel_closed_form() {
    let n = 1.5;
    let lossless = Glazing::new(Glazing::lossless(n), n, 1).expect("a lossless pane");
    assert!((lossless.internal - 1.0).abs() < 1e-12);
    for theta in [0.0f64, 20.0, 45.0, 70.0, 85.0] {
        let c = theta.to_radians().cos();
        let ct = (1.0 - (1.0 - c * c) / (n * n)).sqrt();
        let rs = ((c - n * ct) / (c + n * ct)).powi(2);
        let rp = ((ct - n * c) / (ct + n * c)).powi(2);
        let one = 0.5 * ((1.0 - rs) / (1.0 + rs) + (1.0 - rp) / (1.0 + rp));
        let two = 0.5 * ((1.0 - rs) / (1.0 + 3.0 * rs) + (1.0 - rp) / (1.0 + 3.0 * rp));
        assert!((lossless.transmittance(c) - one).abs() < 1e-12, "{theta}°");
        let double = Glazing { panes: 2, ..lossless };
        assert!((double.transmittance(c) - two).abs() < 1e-12, "{theta}°, two panes");
    }
    assert!((lossless.transmittance(1.0) - 2.0 * n / (n * n + 1.0)).abs() < 1e-12);
    assert_eq!(lossless.transmittance(0.0), 0.0);
}

#[test]
fn the_normal_transmittance_is_met_and_falls_with_incidence() {
    for (tau, panes) in [(0.88, 1), (0.80, 1), (0.88, 2)] {
        let g = Glazing::new(tau, 1.52, panes).expect("a pane");
        let normal = Glazing { panes: 1, ..g }.transmittance(1.0);
        assert!((normal - tau).abs() < 1e-12, "{tau}: {normal}");
        let mut previous = g.transmittance(1.0);
        for k in 1..=90 {
            let t = g.transmittance((k as f64).to_radians().cos());
            assert!(t <= previous + 1e-12 && t >= 0.0, "{tau}, {panes} panes at {k}°");
            previous = t;
        }
    }
    assert!(Glazing::new(0.95, 1.52, 1).is_none(), "more than a lossless pane transmits");
}

#[test]
fn a_glazed_opening_weighs_the_sky_by_the_transmittance_direction_by_direction() {
    let sky = Sky::new(Distribution::General(5), sun(60.0, 180.0), Brightness::Horizontal(10_000.0), 0.0, 0.0);
    let glazing = Glazing::new(0.88, 1.52, 1).unwrap();
    let (o, u, v) = (DVec3::new(1.5, 3.0, 1.5), DVec3::X, DVec3::Z);
    let polygon = ConvexPolygon::quad(o, o + u, o + u + v, o + v);
    let opening = Opening { polygon, glazing: Some(glazing) };
    for (p, n) in [(DVec3::new(2.0, 0.0, 2.0), DVec3::Y), (DVec3::new(2.0, 2.75, 0.0), DVec3::Z)] {
        let mut e = 0.0;
        through_window(&sky, &opening, p, n, &|_| true, 0.0, &mut |_, x, c| {
            assert_eq!(c, Component::Sky);
            e += x;
        });
        let m = 600;
        let mut brute = 0.0;
        for i in 0..m {
            for j in 0..m {
                let x = o + u * ((i as f64 + 0.5) / m as f64) + v * ((j as f64 + 0.5) / m as f64);
                let l = (x - p).normalize();
                let cos = l.dot(n).max(0.0);
                brute += sky.zenith_luminance * glazing.transmittance(l.y) * cos * l.y
                    / (x - p).length_squared()
                    / (m * m) as f64;
            }
        }
        assert!((e / brute - 1.0).abs() < 2e-3, "{p}: {e} against {brute}");
    }
}
