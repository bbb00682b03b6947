//! The horizontal illuminance of the unobstructed sky, `E_h = ∫ L(l) cos Z dω` over the
//! upper hemisphere, by Gauss–Legendre quadrature in `cos Z` (exact for the polynomial
//! skies: the uniform sky's `π L`, the traditional overcast sky's `7π/9 L_z`) and the
//! trapezoidal rule, spectrally accurate for a periodic integrand, in azimuth.

use std::f64::consts::{PI, TAU};

/// Nodes in `cos Z` and in azimuth.
pub const NODES: (usize, usize) = (96, 384);

/// Gauss–Legendre nodes and weights on `[0, 1]` (Newton's iteration on `P_n`).
pub fn gauss_legendre(n: usize) -> Vec<(f64, f64)> {
    (0..n)
        .map(|i| {
            let mut x = (PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
            let mut derivative = 1.0;
            for _ in 0..100 {
                let (mut p0, mut p1) = (1.0, x);
                for k in 2..=n {
                    let p2 = ((2 * k - 1) as f64 * x * p1 - (k - 1) as f64 * p0) / k as f64;
                    p0 = p1;
                    p1 = p2;
                }
                let p = if n == 0 { 1.0 } else { p1 };
                let q = if n == 1 { 1.0 } else { p0 };
                derivative = n as f64 * (x * p - q) / (x * x - 1.0);
                let step = p / derivative;
                x -= step;
                if step.abs() < 1e-16 {
                    break;
                }
            }
            let weight = 2.0 / ((1.0 - x * x) * derivative * derivative);
            (0.5 * (x + 1.0), 0.5 * weight)
        })
        .collect()
}

/// `∫ g(cos Z, azimuth) cos Z dω` over the upper hemisphere.
pub fn hemisphere(g: impl Fn(f64, f64) -> f64) -> f64 {
    let (n, m) = NODES;
    let rule = gauss_legendre(n);
    let step = TAU / m as f64;
    rule.iter().map(|&(u, w)| w * u * (0..m).map(|j| g(u, (j as f64 + 0.5) * step)).sum::<f64>() * step).sum()
}
