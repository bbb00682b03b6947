//! Energy of the blocks: the albedo of every incoming cell,
//! `a(d) = (1/π) Σ_k ρ̄(k,d) μ_k`, is at most 1, and equals its closed form where one exists.

use super::quadrature::{REFERENCE, ggx_albedo, phong_albedo, ring_average};
use super::{LAMBERT, MIRROR, block, matrix};
use ugo::directions::DirectionSet;
use ugo::material::MaterialModel;

#[test]
fn no_cell_reflects_and_transmits_more_than_it_receives() {
    for (model, sets) in matrix() {
        for set in &sets {
            let b = block(&model, set);
            let worst = (0..set.len()).map(|d| b.albedo(d, set)).map(|(r, t)| r + t).fold(0.0, f64::max);
            eprintln!("{model:?} on {}: max albedo {worst:.6}", set.name());
            assert!(worst <= 1.0 + 1e-9, "{model:?} on {}: albedo {worst}", set.name());
        }
    }
}

#[test]
fn lambert_albedo_is_its_reflectance_and_transmittance_in_every_cell() {
    let (_, sets) = matrix().into_iter().find(|(m, _)| *m == LAMBERT).unwrap();
    for set in &sets {
        let b = block(&LAMBERT, set);
        for d in 0..set.len() {
            let (r, t) = b.albedo(d, set);
            assert!((r - 0.6).abs() < 1e-12 && (t - 0.3).abs() < 1e-12, "{} cell {d}: {r} {t}", set.name());
        }
    }
}

#[test]
fn lambert_blocks_are_constant() {
    let b = block(&LAMBERT, &DirectionSet::hemisphere(64));
    assert!(b.values().iter().all(|&v| v == 0.6));
    assert!(b.transmit_values().unwrap().iter().all(|&v| v == 0.3));
    let opaque = block(&MaterialModel::Lambert { reflectance: 0.8, transmittance: 0.0 }, &DirectionSet::klems());
    assert!(!opaque.transmits() && opaque.transmit_at(0, 0).is_none());
}

#[test]
fn mirror_albedo_is_its_reflectance_in_every_cell() {
    let (_, sets) = matrix().into_iter().find(|(m, _)| *m == MIRROR).unwrap();
    let mut worst: f64 = 0.0;
    for set in &sets {
        let b = block(&MIRROR, set);
        for d in 0..set.len() {
            worst = worst.max((b.albedo(d, set).0 - 0.9).abs());
        }
    }
    eprintln!("mirror: max |a(d) − ρ_s| = {worst:.2e}");
    assert!(worst < 1e-9, "{worst}");
}

#[test]
fn one_cell_blocks_are_the_hemispherical_albedo() {
    let single = DirectionSet::single();
    for (model, _) in matrix() {
        let b = block(&model, &single);
        let (r, t) = b.albedo(0, &single);
        assert!((b.at(0, 0) - r).abs() < 1e-14, "{model:?}: K = 1 block {} vs albedo {r}", b.at(0, 0));
        assert!((b.transmit_at(0, 0).unwrap_or(0.0) - t).abs() < 1e-14, "{model:?}");
        let expected = match model {
            MaterialModel::Lambert { reflectance, .. } => reflectance,
            MaterialModel::Mirror { reflectance } => reflectance,
            MaterialModel::Phong { diffuse, specular, exponent } => {
                diffuse + specular * ring_average(0.0, 1.0, 6, |theta| phong_albedo(exponent, theta, REFERENCE))
            }
            MaterialModel::Ggx { diffuse, specular, roughness } => {
                diffuse + specular * ring_average(0.0, 1.0, 6, |theta| ggx_albedo(roughness, theta, REFERENCE))
            }
        };
        eprintln!("{model:?}: K = 1 block {:.6}, hemispherical albedo {expected:.6}", b.at(0, 0));
        assert!((b.at(0, 0) - expected).abs() < 1.2e-3, "{model:?}: {} vs {expected}", b.at(0, 0));
    }
    assert_eq!(block(&LAMBERT, &single).at(0, 0), 0.6);
    assert_eq!(block(&LAMBERT, &single).transmit_at(0, 0), Some(0.3));
    assert!((block(&MIRROR, &single).at(0, 0) - 0.9).abs() < 1e-12);
}

#[test]
fn no_cell_gains_energy_at_the_parameter_limits() {
    let set = DirectionSet::hemisphere(16);
    let limits = [
        MaterialModel::Ggx { diffuse: 0.0, specular: 1.0, roughness: 0.001 },
        MaterialModel::Phong { diffuse: 0.0, specular: 1.0, exponent: 1e5 },
        MaterialModel::Phong { diffuse: 0.0, specular: 1.0, exponent: 0.0 },
    ];
    for model in limits {
        let b = block(&model, &set);
        let worst = (0..set.len()).map(|d| b.albedo(d, &set).0).fold(0.0, f64::max);
        eprintln!("{model:?} on 16: max albedo {worst:.9}");
        assert!(worst <= 1.0 + 1e-9, "{model:?}: {worst}");
    }
}
