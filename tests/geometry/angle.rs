//! `geometry::angle`, the contour integral's `atan2(s, c)` for `s ≥ 0`, against the C
//! library's `atan2` over the whole half-turn: every octant and its borders, angles down to
//! 1e-12 rad and up to within 1e-12 of π, and scales from 1e-200 to 1e200.

use std::f64::consts::{FRAC_PI_2, FRAC_PI_4, PI};
use ugo::geometry::angle;

/// The relative error allowed: about one unit in the last place of the polynomial, the
/// reduction's division and its addition of π/4, π/2 or π.
const WITHIN: f64 = 5e-16;

fn relative_error(s: f64, c: f64) -> f64 {
    let exact = s.atan2(c);
    (angle(s, c) - exact).abs() / exact.max(f64::MIN_POSITIVE)
}

#[test]
fn the_angle_is_atan2_to_within_5e_16_of_itself() {
    let mut state = 0x9e37_79b9_7f4a_7c15_u64;
    let mut uniform = || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut worst = 0.0_f64;
    for i in 0..1_000_000 {
        let theta = match i % 3 {
            0 => PI * uniform(),
            1 => uniform().powi(12),
            _ => PI - uniform().powi(12),
        };
        let scale = 10f64.powf(400.0 * uniform() - 200.0);
        worst = worst.max(relative_error(scale * theta.sin(), scale * theta.cos()));
    }
    assert!(worst <= WITHIN, "largest relative error {worst:e}");
}

#[test]
fn the_borders_of_the_octants_and_the_axes_are_within_two_epsilons() {
    let sqrt_half = 0.5f64.sqrt();
    for (s, c, expected) in [
        (0.0, 1.0, 0.0),
        (0.0, -1.0, PI),
        (1.0, 0.0, FRAC_PI_2),
        (1.0, -0.0, FRAC_PI_2),
        (sqrt_half, sqrt_half, FRAC_PI_4),
        (sqrt_half, -sqrt_half, 3.0 * FRAC_PI_4),
        (0.0, 0.0, 0.0),
    ] {
        let got = angle(s, c);
        assert!((got - expected).abs() <= 2.0 * f64::EPSILON * expected, "angle({s}, {c}) = {got}, not {expected}");
    }
    let tan_pi_8 = (PI / 8.0).tan();
    for c in [1.0, -1.0] {
        for s in [tan_pi_8 * (1.0 - 1e-16), tan_pi_8, tan_pi_8 * (1.0 + 1e-16), 1.0 / tan_pi_8] {
            assert!(relative_error(s, c) <= WITHIN, "angle({s}, {c})");
        }
    }
}
