//! Reciprocity as the double cell average keeps it: `ρ̄(k,d) = ρ̄(d,k)`. Lambert blocks are
//! exactly symmetric; mirror and glossy blocks are computed by quadrature of the incoming
//! cell (and lobe sampling), so they are symmetric to quadrature accuracy. The measure is
//! `max |ρ̄(k,d) − ρ̄(d,k)| / max ρ̄`.

use super::{LAMBERT, MIRROR, block, matrix};
use ugo::material::MaterialModel;

fn asymmetry(values: &[f64], k: usize) -> f64 {
    let largest = values.iter().copied().fold(0.0, f64::max);
    let mut worst: f64 = 0.0;
    for a in 0..k {
        for b in 0..a {
            worst = worst.max((values[a * k + b] - values[b * k + a]).abs());
        }
    }
    worst / largest
}

#[test]
fn lambert_blocks_are_exactly_symmetric() {
    let (_, sets) = matrix().into_iter().find(|(m, _)| *m == LAMBERT).unwrap();
    for set in &sets {
        let b = block(&LAMBERT, set);
        assert_eq!(asymmetry(b.values(), set.len()), 0.0);
        assert_eq!(asymmetry(b.transmit_values().unwrap(), set.len()), 0.0);
    }
}

#[test]
fn mirror_blocks_are_symmetric() {
    let (_, sets) = matrix().into_iter().find(|(m, _)| *m == MIRROR).unwrap();
    for set in &sets {
        let a = asymmetry(block(&MIRROR, set).values(), set.len());
        eprintln!("mirror on {}: asymmetry {a:.2e}", set.name());
        assert!(a < 1e-12, "{}: {a}", set.name());
    }
}

/// Measured (docs/materials.md): at most 1.5e-2 for Phong `n = 1` at `K = 64`, where a
/// horizon cell meets a near-normal one far out in the broad lobe (few lobe samples land
/// there; the sign of the error varies from pair to pair), and at most 3.8e-3 otherwise.
fn tolerance(model: &MaterialModel) -> f64 {
    match model {
        MaterialModel::Phong { exponent, .. } if *exponent < 10.0 => 2e-2,
        _ => 5e-3,
    }
}

#[test]
fn glossy_blocks_are_symmetric_to_quadrature_accuracy() {
    for (model, sets) in
        matrix().into_iter().filter(|(m, _)| !matches!(m, MaterialModel::Lambert { .. } | MaterialModel::Mirror { .. }))
    {
        for set in &sets {
            let a = asymmetry(block(&model, set).values(), set.len());
            eprintln!("{model:?} on {}: asymmetry {a:.2e}", set.name());
            assert!(a < tolerance(&model), "{model:?} on {}: {a}", set.name());
        }
    }
}
