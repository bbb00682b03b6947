//! The light through an opening (`ugo::sky::through_window`): exact for the uniform sky
//! (`E = π L F`, F the exact configuration factor to the opening) and, for the graded CIE
//! skies, equal to a brute-force integral over the opening's area written out here.

use super::sun;
use crate::support::over_parallelogram;
use glam::DVec3;
use std::f64::consts::PI;
use ugo::geometry::ConvexPolygon;
use ugo::sky::{Brightness, Component, Distribution, ETA, Opening, Sky, through_window};
use ugo::transfer::contour::point_to_polygon;

fn sky(distribution: Distribution, ground: f64) -> Sky {
    Sky::new(distribution, sun(60.0, 180.0), Brightness::Horizontal(10_000.0), ground, 0.0)
}

/// `(SC, ERC)` at `p` facing `n` through `window`, nothing in the way, lx.
fn components(sky: &Sky, window: &ConvexPolygon, p: DVec3, n: DVec3) -> (f64, f64) {
    let (mut s, mut g) = (0.0, 0.0);
    let opening = Opening { polygon: *window, glazing: None };
    through_window(ETA, sky, &opening, p, n, &|_: DVec3| true, 0.0, &mut |_, e, c| match c {
        Component::Sky => s += e,
        Component::Ground => g += e,
    });
    (s, g)
}

/// `Σ L(l) cos θ cos θ' / r² ΔA` over an `m × m` grid of the parallelogram `o + s u + t v`.
fn brute_force(sky: &Sky, o: DVec3, u: DVec3, v: DVec3, p: DVec3, n: DVec3, m: usize) -> f64 {
    over_parallelogram(o, u, v, p, m, |l, solid_angle| sky.luminance(l) * l.dot(n).max(0.0) * solid_angle)
}

#[test]
fn the_uniform_sky_gives_pi_l_times_the_configuration_factor_exactly() {
    let uniform = sky(Distribution::General(5), 0.0);
    let window = ConvexPolygon::quad(
        DVec3::new(1.5, 3.0, 1.5),
        DVec3::new(2.5, 3.0, 1.5),
        DVec3::new(2.5, 3.0, 2.5),
        DVec3::new(1.5, 3.0, 2.5),
    );
    // CIE 171 5.9, type 5, 1 × 1 m opening: the wall points A–F (`docs/references.md`).
    for (i, reference) in [1.04, 2.39, 2.59, 2.20, 1.70, 1.27].into_iter().enumerate() {
        let (p, n) = (DVec3::new(2.0, 2.75 - 0.5 * i as f64, 0.0), DVec3::Z);
        let (sc, erc) = components(&uniform, &window, p, n);
        let f = point_to_polygon(p, n, &window.reversed()).max(point_to_polygon(p, n, &window));
        assert!((sc / (10_000.0 * f) - 1.0).abs() < 1e-12, "{i}: SC {sc} lx, F {f}");
        assert_eq!(erc, 0.0);
        assert!((100.0 * sc / 10_000.0 - reference).abs() < 0.005 + 1e-9, "{i}: {} % against {reference}", sc / 100.0);
    }
}

#[test]
fn graded_skies_agree_with_a_brute_force_integral_over_the_opening() {
    // A facade opening 2 × 1 m with a 1 m sill in the wall z = 0 (the sky towards −z),
    // seen from the floor, the back wall and the ceiling: sky above, ground below.
    let (o, u, v) = (DVec3::new(1.0, 1.0, 0.0), DVec3::new(2.0, 0.0, 0.0), DVec3::new(0.0, 1.0, 0.0));
    let window = ConvexPolygon::quad(o, o + u, o + u + v, o + v);
    let points = [
        (DVec3::new(2.0, 0.0, 0.25), DVec3::Y),
        (DVec3::new(2.0, 0.0, 2.25), DVec3::Y),
        (DVec3::new(2.0, 1.25, 4.0), DVec3::NEG_Z),
        (DVec3::new(2.0, 2.75, 4.0), DVec3::NEG_Z),
        (DVec3::new(2.0, 3.0, 1.75), DVec3::NEG_Y),
    ];
    for distribution in [Distribution::Overcast, Distribution::General(8), Distribution::General(15)] {
        let outside = Sky::new(distribution, sun(60.0, 0.0), Brightness::Horizontal(10_000.0), 0.3, 0.0);
        for (p, n) in points {
            let (sc, erc) = components(&outside, &window, p, n);
            let brute = brute_force(&outside, o, u, v, p, n, 800);
            assert!(((sc + erc) / brute - 1.0).abs() < 2e-3, "{distribution:?} at {p}: {} against {brute}", sc + erc);
            if p.y >= 2.0 {
                assert_eq!(sc, 0.0, "{p} sees only the ground");
                let f = point_to_polygon(p, n, &window).max(point_to_polygon(p, n, &window.reversed()));
                assert!((erc / (PI * outside.ground_luminance() * f) - 1.0).abs() < 1e-12);
            }
        }
    }
}
