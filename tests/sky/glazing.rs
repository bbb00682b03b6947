//! Glazing (`ugo::sky::Glazing`). The Fresnel model of one and two panes against its closed
//! forms: a lossless pane transmits `(1 − r)/(1 + r)` per polarisation, `2n/(n² + 1)` at
//! normal incidence; the normal transmittance asked for is met exactly; nothing passes at
//! grazing incidence; two lossless panes transmit `(1 − r)/(1 + 3r)` per polarisation.
//! CIE 171's clear glass: its polynomial at exact decimal values, its hemispherical
//! transmittance against the polynomial's closed-form integral, and a glazed roof as large
//! as the sky transmitting `π L τ_d` of a uniform sky. A glazed opening under a graded sky
//! gives `∫ L τ(θ) cos θ' dω` (a brute-force sum), for both models.

use super::sun;
use glam::DVec3;
use std::f64::consts::PI;
use ugo::geometry::ConvexPolygon;
use ugo::sky::{
    Brightness, CIE171_GLASS, Component, Distribution, ETA, Fresnel, Glazing, Opening, Sky, gauss_legendre,
    through_window,
};

#[test]
fn a_lossless_pane_transmits_the_fresnel_closed_form() {
    let n = 1.5;
    let lossless = Fresnel::new(Fresnel::lossless(n), n, 1).expect("a lossless pane");
    assert!((lossless.internal - 1.0).abs() < 1e-12);
    for theta in [0.0f64, 20.0, 45.0, 70.0, 85.0] {
        let c = theta.to_radians().cos();
        let ct = (1.0 - (1.0 - c * c) / (n * n)).sqrt();
        let rs = ((c - n * ct) / (c + n * ct)).powi(2);
        let rp = ((ct - n * c) / (ct + n * c)).powi(2);
        let one = 0.5 * ((1.0 - rs) / (1.0 + rs) + (1.0 - rp) / (1.0 + rp));
        let two = 0.5 * ((1.0 - rs) / (1.0 + 3.0 * rs) + (1.0 - rp) / (1.0 + 3.0 * rp));
        assert!((lossless.transmittance(c) - one).abs() < 1e-12, "{theta}°");
        let double = Fresnel { panes: 2, ..lossless };
        assert!((double.transmittance(c) - two).abs() < 1e-12, "{theta}°, two panes");
    }
    assert!((lossless.transmittance(1.0) - 2.0 * n / (n * n + 1.0)).abs() < 1e-12);
    assert_eq!(lossless.transmittance(0.0), 0.0);
}

#[test]
fn the_normal_transmittance_is_met_and_falls_with_incidence() {
    for (tau, panes) in [(0.88, 1), (0.80, 1), (0.88, 2)] {
        let g = Fresnel::new(tau, 1.52, panes).expect("a pane");
        let normal = Fresnel { panes: 1, ..g }.transmittance(1.0);
        assert!((normal - tau).abs() < 1e-12, "{tau}: {normal}");
        let mut previous = g.transmittance(1.0);
        for k in 1..=90 {
            let t = g.transmittance((k as f64).to_radians().cos());
            assert!(t <= previous + 1e-12 && t >= 0.0, "{tau}, {panes} panes at {k}°");
            previous = t;
        }
    }
    assert!(Fresnel::new(0.95, 1.52, 1).is_none(), "more than a lossless pane transmits");
}

#[test]
fn a_glazed_opening_weighs_the_sky_by_the_transmittance_direction_by_direction() {
    let sky = Sky::new(Distribution::General(5), sun(60.0, 180.0), Brightness::Horizontal(10_000.0), 0.0, 0.0);
    let fresnel = Glazing::Fresnel(Fresnel::new(0.88, 1.52, 1).unwrap());
    let (o, u, v) = (DVec3::new(1.5, 3.0, 1.5), DVec3::X, DVec3::Z);
    let polygon = ConvexPolygon::quad(o, o + u, o + u + v, o + v);
    for glazing in [fresnel, Glazing::Cie171] {
        let opening = Opening { polygon, glazing: Some(glazing) };
        for (p, n) in [(DVec3::new(2.0, 0.0, 2.0), DVec3::Y), (DVec3::new(2.0, 2.75, 0.0), DVec3::Z)] {
            let e = through(&sky, &opening, p, n);
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
            assert!((e / brute - 1.0).abs() < 2e-3, "{glazing}, {p}: {e} against {brute}");
        }
    }
}

/// The sky through `opening` at `p` facing `n`, lx.
fn through(sky: &Sky, opening: &Opening, p: DVec3, n: DVec3) -> f64 {
    let mut e = 0.0;
    through_window(ETA, sky, opening, p, n, &|_: DVec3| true, 0.0, &mut |_, x, c| {
        assert_eq!(c, Component::Sky);
        e += x;
    });
    e
}

/// CIE 171's `τ(c)` term by term, `c^k` by repeated products.
fn cie171_terms(c: f64) -> f64 {
    (0..6).map(|k| CIE171_GLASS[k] * (0..k).fold(1.0, |power, _| power * c)).sum()
}

#[test]
fn cie_171_glass_transmits_its_polynomial() {
    // τ(c) = −0.028378 + 3.156075 c − 3.058376 c² − 1.428919 c³ + 4.014235 c⁴ − 1.775827 c⁵
    // (CIE 171 test 5.5, Tregenza 1987), evaluated in exact decimal arithmetic.
    let exact =
        [(1.0, 0.87881), (0.8, 0.86984249664), (0.5, 0.80184571875), (0.2, 0.47492511936), (0.1, 0.25560048623)];
    for (c, tau) in exact {
        let t = Glazing::Cie171.transmittance(c);
        assert!((t - tau).abs() < 1e-12, "cos θ = {c}: {t} against {tau}");
        assert_eq!(Glazing::Cie171.transmittance(-c), t, "the sign of the cosine is ignored");
    }
    // Below c = 0.00907 (89.48°) the polynomial is negative and the glass transmits nothing.
    assert!(cie171_terms(0.0) < 0.0 && cie171_terms(0.009) < 0.0 && cie171_terms(0.0091) > 0.0);
    for c in [0.0, 0.005, 0.009] {
        assert_eq!(Glazing::Cie171.transmittance(c), 0.0, "{c}");
    }
    // Within 0.5 % of its normal value to 30°, falling beyond 60° (the fit's shape).
    for degrees in [10.0f64, 20.0, 30.0] {
        let t = Glazing::Cie171.transmittance(degrees.to_radians().cos());
        assert!((t / 0.87881 - 1.0).abs() < 5e-3, "{degrees}°: {t}");
    }
    let mut previous = 1.0;
    for degrees in 60..=90 {
        let t = Glazing::Cie171.transmittance((degrees as f64).to_radians().cos());
        assert!(t < previous || t == 0.0, "{degrees}°: {t}");
        previous = t;
    }
}

#[test]
fn cie_171_glass_transmits_its_closed_form_hemispherical_transmittance() {
    // τ_d = 2 ∫ max(τ(c), 0) c dc = Σ 2 a_k (1 − c₀^{k+2})/(k + 2), c₀ the root near 0.
    let (mut lo, mut hi) = (0.0, 0.1);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if cie171_terms(mid) < 0.0 { lo = mid } else { hi = mid }
    }
    let c0: f64 = 0.5 * (lo + hi);
    let closed: f64 = (0..6).map(|k| 2.0 * CIE171_GLASS[k] * (1.0 - c0.powi(k as i32 + 2)) / (k as f64 + 2.0)).sum();
    assert!((closed - 0.805616).abs() < 1e-6, "{closed}");
    // Gauss–Legendre over [0, 1], the clamp's kink at c₀ limiting it to about 1e-8.
    let quadrature: f64 =
        gauss_legendre(200).iter().map(|&(c, w)| w * 2.0 * c * Glazing::Cie171.transmittance(c)).sum();
    assert!((quadrature - closed).abs() < 3e-8, "{quadrature} against {closed}");
    // A glazed roof 204.8 m square, 1 m above the point, under a uniform sky: E = π L τ_d
    // (the directions it misses, within 0.6° of the horizon, carry under 1e-5 of E). The
    // roof is tiled into openings growing geometrically from the point, 0.1 m to 102.4 m,
    // so that each is cut finely enough; the pieces' centroid rule (`ETA` = 0.1) is then
    // good to about 1e-4.
    let sky = Sky::new(Distribution::General(5), sun(60.0, 180.0), Brightness::Zenith(1.0), 0.0, 0.0);
    let half: Vec<f64> = (0..=10).map(|k| 0.1 * 2f64.powi(k)).collect();
    let edges: Vec<f64> = half.iter().rev().map(|x| -x).chain([0.0]).chain(half.iter().copied()).collect();
    let mut e = 0.0;
    for x in edges.windows(2) {
        for z in edges.windows(2) {
            let corner = |i: usize, j: usize| DVec3::new(x[i], 1.0, z[j]);
            let polygon = ConvexPolygon::quad(corner(0, 0), corner(1, 0), corner(1, 1), corner(0, 1));
            e += through(&sky, &Opening { polygon, glazing: Some(Glazing::Cie171) }, DVec3::ZERO, DVec3::Y);
        }
    }
    assert!((e / (PI * closed) - 1.0).abs() < 3e-4, "{e} against {}", PI * closed);
}
