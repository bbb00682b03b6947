//! Normalized Phong blocks against the independent quadrature of `quadrature.rs`: the
//! reference itself against the published albedo table, every cell's albedo against the
//! cell average of `a(θ)`, and the normal-incidence cell against `k_d + k_s`.

use super::quadrature::{REFERENCE, phong_albedo, ring_average};
use super::{block, matrix, rings};
use ugo::material::MaterialModel;

/// Albedo of the lobe with `k_s = 1` (docs/references.md, "Glossy and specular cases"), 3 decimals.
const TABLE: [(f64, [f64; 4]); 3] =
    [(1.0, [1.000, 0.881, 0.609, 0.410]), (10.0, [1.000, 0.866, 0.505, 0.228]), (100.0, [1.000, 0.866, 0.500, 0.175])];

#[test]
fn reference_reproduces_the_published_phong_albedo_table() {
    for (n, row) in TABLE {
        for (theta, expected) in [0.0, 30.0, 60.0, 80.0f64].into_iter().zip(row) {
            let a = phong_albedo(n, theta.to_radians(), REFERENCE);
            assert!((a - expected).abs() <= 5e-4, "n = {n}, θ = {theta}°: {a} vs {expected}");
        }
    }
}

#[test]
fn reference_phong_albedo_is_exactly_k_s_at_normal_incidence() {
    for n in [1.0, 10.0, 100.0, 1000.0] {
        let a = phong_albedo(n, 0.0, REFERENCE);
        assert!((a - 1.0).abs() < 1e-12, "n = {n}: {a}");
    }
}

#[test]
fn reference_phong_albedo_is_cos_theta_where_the_horizon_does_not_clip_the_lobe() {
    for (n, theta) in [(1000.0, 30.0), (1000.0, 60.0), (100.0, 30.0f64)] {
        let a = phong_albedo(n, theta.to_radians(), REFERENCE);
        assert!((a - theta.to_radians().cos()).abs() < 1e-9, "n = {n}, θ = {theta}°: {a}");
    }
}

/// `k_d + k_s ā` with `ā` the reference cell average of the lobe albedo over a ring.
fn expected(model: &MaterialModel, bottom: f64, top: f64) -> f64 {
    let MaterialModel::Phong { diffuse, specular, exponent } = *model else { unreachable!() };
    diffuse + specular * ring_average(bottom, top, 6, |theta| phong_albedo(exponent, theta, REFERENCE))
}

#[test]
fn phong_block_albedo_matches_the_independent_cell_average_in_every_cell() {
    for (model, sets) in matrix().into_iter().filter(|(m, _)| matches!(m, MaterialModel::Phong { .. })) {
        // K = 1 is `one_cell_blocks_are_the_hemispherical_albedo`
        for set in sets.iter().filter(|s| s.len() > 1) {
            let b = block(&model, set);
            let mut worst: f64 = 0.0;
            for (bottom, top, cells) in rings(set) {
                let reference = expected(&model, bottom, top);
                for d in cells {
                    worst = worst.max((b.albedo(d, set).0 - reference).abs());
                }
            }
            eprintln!("{model:?} on {}: max |a(d) − reference| = {worst:.2e}", set.name());
            assert!(worst < 8e-4, "{model:?} on {}: {worst}", set.name());
        }
    }
}

/// At normal incidence the lobe albedo is exactly `k_s`. Off normal, a lobe that the
/// horizon does not clip has albedo exactly `k_s cosθ_i` (its mean direction is the mirror
/// direction), and clipping only adds. So the cap cell lies between
/// `k_d + k_s ⟨cosθ⟩_cap` (reached for large `n`) and `k_d + k_s`, and tends to `k_d + k_s`
/// as the cap shrinks (`⟨cosθ⟩_cap = (2/3)(1 − c³)/(1 − c²)`, `c` the cap's edge).
#[test]
fn phong_lobe_integrates_to_its_specular_reflectance_at_normal_incidence() {
    for (model, sets) in matrix().into_iter().filter(|(m, _)| matches!(m, MaterialModel::Phong { .. })) {
        let MaterialModel::Phong { diffuse, specular, exponent: n } = model else { unreachable!() };
        let mut shortfall = Vec::new();
        for set in sets.iter().filter(|s| s.len() > 1) {
            let (c, _, _, _) = set.bounds(0);
            let a = block(&model, set).albedo(0, set).0;
            let unclipped = diffuse + specular * (2.0 / 3.0) * (1.0 - c.powi(3)) / (1.0 - c * c);
            let reference = expected(&model, c, 1.0);
            let cap = c.acos().to_degrees();
            eprintln!(
                "n = {n}, cap {cap:.2}° of {}: a = {a:.6}, reference {reference:.6}, k_d + k_s⟨cosθ⟩ = {unclipped:.6}",
                set.name()
            );
            assert!((a - reference).abs() < 5e-4, "n = {n} on {}: {a} vs {reference}", set.name());
            assert!(a > unclipped - 5e-4 && a < diffuse + specular, "n = {n} on {}: {a}", set.name());
            if n >= 10.0 {
                assert!((a - unclipped).abs() < 5e-4, "n = {n} on {}: {a} vs {unclipped}", set.name());
            }
            shortfall.push(diffuse + specular - a);
        }
        // the cap's solid angle drops fourfold from K = 16 to 64, and so does the shortfall
        if let [s16, s64, ..] = shortfall[..] {
            assert!((0.2..0.3).contains(&(s64 / s16)), "n = {n}: shortfall ratio {}", s64 / s16);
        }
    }
}
