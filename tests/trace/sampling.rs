//! The material sampler against its own density and luminance factor: for every model and
//! several outgoing directions, two independent Monte Carlo estimates of the directional
//! albedo `a(l) = (1/π) ∫ ρ(l, l') |cosθ'| dω'` agree (the mean weight of `sample`, and
//! uniform sampling of the sphere with `evaluate`), and `pdf` integrates to at most 1
//! (exactly 1 for Lambert, and for Phong at normal incidence, whose lobe then stays above
//! the horizon). Multiple importance sampling
//! is unbiased only if `pdf` is the density `sample` really draws from; a wrong `pdf`
//! changes the mean weight and fails the first check.

use glam::DVec3;
use std::f64::consts::{FRAC_1_PI, PI, TAU};
use ugo::material::MaterialModel;
use ugo::random::Rng;

const N: usize = 200_000;

fn outgoing(theta_deg: f64) -> DVec3 {
    let t = theta_deg.to_radians();
    DVec3::new(t.sin(), 0.0, t.cos())
}

/// A uniform direction on the sphere (density 1/4π).
fn sphere(rng: &mut Rng) -> DVec3 {
    let z = 1.0 - 2.0 * rng.uniform();
    let r = (1.0 - z * z).max(0.0).sqrt();
    let phi = TAU * rng.uniform();
    DVec3::new(r * phi.cos(), r * phi.sin(), z)
}

/// Mean and standard error of `f` over `N` samples.
fn mean(rng: &mut Rng, mut f: impl FnMut(&mut Rng) -> f64) -> (f64, f64) {
    let (mut s, mut q) = (0.0, 0.0);
    for _ in 0..N {
        let x = f(rng);
        s += x;
        q += x * x;
    }
    let m = s / N as f64;
    (m, ((q / N as f64 - m * m) / (N as f64 - 1.0)).max(0.0).sqrt())
}

#[test]
fn sampled_weights_and_densities_match_the_luminance_factor() {
    let models = [
        MaterialModel::Lambert { reflectance: 0.6, transmittance: 0.3 },
        MaterialModel::Phong { diffuse: 0.2, specular: 0.7, exponent: 20.0 },
        MaterialModel::Phong { diffuse: 0.0, specular: 1.0, exponent: 2.0 },
        MaterialModel::Ggx { diffuse: 0.1, specular: 0.8, roughness: 0.3 },
        MaterialModel::Ggx { diffuse: 0.3, specular: 0.6, roughness: 0.7 },
    ];
    let mut rng = Rng::stream(7, 0);
    for model in &models {
        for theta in [0.0, 35.0, 70.0] {
            let l = outgoing(theta);
            let (weight, we) = mean(&mut rng, |r| model.sample(l, r.uniform3()).map_or(0.0, |s| s.weight));
            let (albedo, ae) = mean(&mut rng, |r| {
                let d = sphere(r);
                4.0 * PI * model.luminance_factor(l, d) * d.z.abs() * FRAC_1_PI
            });
            let (total, te) = mean(&mut rng, |r| 4.0 * PI * model.pdf(l, sphere(r)));
            let z = (weight - albedo) / (we * we + ae * ae).sqrt();
            eprintln!(
                "{model:?} at {theta}°: mean weight {weight:.4} ± {we:.4}, albedo {albedo:.4} ± {ae:.4} (z {z:+.2}), ∫pdf {total:.4} ± {te:.4}"
            );
            assert!(z.abs() < 4.0, "z {z}");
            assert!(total < 1.0 + 4.0 * te, "∫pdf {total}");
            let whole = match model {
                MaterialModel::Phong { .. } => theta == 0.0,
                _ => matches!(model, MaterialModel::Lambert { .. }),
            };
            if whole {
                assert!((total - 1.0).abs() < 4.0 * te + 1e-3, "∫pdf {total}");
            }
        }
    }
}
