//! Real spherical and hemispherical harmonics: known values, orthonormality by
//! Gauss–Legendre × trapezoid quadrature (exact for these degrees), the addition theorem,
//! and the error decay of hemispherical expansions of smooth functions.

use std::f64::consts::{PI, TAU};
use ugo::basis::sh::{count, hemispherical, index, real_sh};

const LMAX: usize = 12;

/// Gauss–Legendre nodes and weights on [−1, 1] (Newton on `P_n`).
fn gauss_legendre(n: usize) -> Vec<(f64, f64)> {
    (0..n)
        .map(|i| {
            let mut x = (PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
            loop {
                let (mut p0, mut p1) = (1.0, x);
                for k in 2..=n {
                    (p0, p1) = (p1, ((2 * k - 1) as f64 * x * p1 - (k - 1) as f64 * p0) / k as f64);
                }
                let dp = n as f64 * (x * p1 - p0) / (x * x - 1.0);
                let step = p1 / dp;
                x -= step;
                if step.abs() < 1e-15 {
                    let w = 2.0 / ((1.0 - x * x) * dp * dp);
                    return (x, w);
                }
            }
        })
        .collect()
}

/// `∫ f_a f_b dω` for all pairs over the sphere (`z ∈ [−1,1]`) or the upper hemisphere.
fn gram(hemisphere: bool) -> Vec<Vec<f64>> {
    let m = count(LMAX);
    let mut g = vec![vec![0.0; m]; m];
    let mut y = vec![0.0; m];
    let phis = 4 * LMAX + 4;
    for (x, w) in gauss_legendre(2 * LMAX + 2) {
        let (z, w) = if hemisphere { (0.5 * (x + 1.0), 0.5 * w) } else { (x, w) };
        for p in 0..phis {
            let phi = TAU * p as f64 / phis as f64;
            if hemisphere {
                hemispherical(LMAX, z, phi, &mut y)
            } else {
                real_sh(LMAX, z, phi, &mut y)
            }
            let weight = w * TAU / phis as f64;
            for a in 0..m {
                for b in 0..m {
                    g[a][b] += weight * y[a] * y[b];
                }
            }
        }
    }
    g
}

fn assert_identity(g: &[Vec<f64>], what: &str) {
    let worst = (0..g.len())
        .flat_map(|a| (0..g.len()).map(move |b| (a, b)))
        .map(|(a, b)| (g[a][b] - if a == b { 1.0 } else { 0.0 }).abs())
        .fold(0.0, f64::max);
    assert!(worst < 1e-10, "{what}: Gram matrix differs from the identity by {worst:.2e}");
}

#[test]
fn spherical_harmonics_are_orthonormal_up_to_degree_twelve() {
    assert_identity(&gram(false), "Y_lm over the sphere");
}

#[test]
fn hemispherical_harmonics_are_orthonormal_over_the_hemisphere() {
    assert_identity(&gram(true), "H_lm over the hemisphere");
}

#[test]
fn known_values_of_the_first_bands() {
    let (x, y, z) = (0.36_f64, -0.48_f64, 0.8_f64);
    let phi = y.atan2(x);
    let mut v = vec![0.0; count(2)];
    real_sh(2, z, phi, &mut v);
    let c1 = (3.0 / (4.0 * PI)).sqrt();
    let expected = [
        (index(0, 0), 0.5 / PI.sqrt()),
        (index(1, -1), c1 * y),
        (index(1, 0), c1 * z),
        (index(1, 1), c1 * x),
        (index(2, -2), (15.0 / (4.0 * PI)).sqrt() * x * y),
        (index(2, 0), (5.0 / (16.0 * PI)).sqrt() * (3.0 * z * z - 1.0)),
        (index(2, 2), (15.0 / (16.0 * PI)).sqrt() * (x * x - y * y)),
    ];
    for (n, value) in expected {
        assert!((v[n] - value).abs() < 1e-14, "Y_{n} = {} expected {value}", v[n]);
    }
}

#[test]
fn band_energy_is_the_same_in_every_direction() {
    // Addition theorem: Σ_m Y_lm(ω)² = (2l + 1)/(4π), whatever ω (rotation invariance).
    let mut v = vec![0.0; count(LMAX)];
    for (z, phi) in [(0.93, 0.2), (-0.41, 2.9), (0.0, 5.5), (1.0, 0.0), (-0.999, 4.1)] {
        real_sh(LMAX, z, phi, &mut v);
        for l in 0..=LMAX {
            let energy: f64 = (0..=2 * l).map(|j| v[l * l + j].powi(2)).sum();
            let exact = (2 * l + 1) as f64 / (4.0 * PI);
            assert!((energy / exact - 1.0).abs() < 1e-12, "l = {l} at z = {z}: {energy} vs {exact}");
        }
    }
}

#[test]
fn hemispherical_expansions_of_smooth_functions_converge() {
    // A glossy lobe about a tilted axis and a smooth axisymmetric sky gradient. (A function
    // with a first-order azimuthal term at the horizon, such as sinθ cosφ, converges only
    // algebraically: HSH carry √(cosθ) there, not √(1 + cosθ); docs/basis.md.)
    let axis = [0.5_f64, 0.0, 0.75_f64.sqrt()];
    let lobe = |x: f64, y: f64, z: f64| (x * axis[0] + y * axis[1] + z * axis[2]).max(0.0).powi(8);
    let sky = |_x: f64, _y: f64, z: f64| (1.0 + 2.0 * z) * (0.7 * z).exp();
    for (name, f) in [("lobe", &lobe as &dyn Fn(f64, f64, f64) -> f64), ("sky", &sky)] {
        let nodes = gauss_legendre(40);
        let phis = 96;
        let points: Vec<(f64, f64, f64)> = nodes
            .iter()
            .flat_map(|&(x, w)| {
                (0..phis).map(move |p| (0.5 * (x + 1.0), TAU * p as f64 / phis as f64, 0.5 * w * TAU / phis as f64))
            })
            .collect();
        let mut errors = Vec::new();
        for lmax in [1, 2, 4, 6, 8] {
            let m = count(lmax);
            let mut coefficients = vec![0.0; m];
            let mut y = vec![0.0; m];
            let value = |z: f64, phi: f64| {
                let s = (1.0 - z * z).sqrt();
                f(s * phi.cos(), s * phi.sin(), z)
            };
            for &(z, phi, w) in &points {
                hemispherical(lmax, z, phi, &mut y);
                let fv = value(z, phi);
                coefficients.iter_mut().zip(&y).for_each(|(c, y)| *c += w * fv * y);
            }
            let (mut error, mut norm) = (0.0, 0.0);
            for &(z, phi, w) in &points {
                hemispherical(lmax, z, phi, &mut y);
                let approx: f64 = coefficients.iter().zip(&y).map(|(c, y)| c * y).sum();
                let fv = value(z, phi);
                error += w * (approx - fv).powi(2);
                norm += w * fv * fv;
            }
            errors.push((error / norm).sqrt());
        }
        for pair in errors.windows(2) {
            assert!(pair[1] < 0.7 * pair[0], "{name}: L² errors {errors:?} do not decay");
        }
        assert!(errors[4] < 1e-2, "{name}: L² errors {errors:?}");
    }
}
