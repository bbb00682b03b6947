//! GGX blocks against the independent quadrature of `quadrature.rs`: every cell's albedo
//! against the cell average of the GGX + height-correlated Smith albedo `a(θ)`.

use super::quadrature::{REFERENCE, ggx_albedo, ring_average};
use super::{block, matrix, rings};
use ugo::material::MaterialModel;

#[test]
fn ggx_block_albedo_matches_the_independent_cell_average_in_every_cell() {
    for (model, sets) in matrix().into_iter().filter(|(m, _)| matches!(m, MaterialModel::Ggx { .. })) {
        let MaterialModel::Ggx { diffuse, specular, roughness } = model else { unreachable!() };
        // K = 1 is `one_cell_blocks_are_the_hemispherical_albedo`
        for set in sets.iter().filter(|s| s.len() > 1) {
            let b = block(&model, set);
            let (mut worst, mut at): (f64, f64) = (0.0, 0.0); // signed error, ring top
            for (bottom, top, cells) in rings(set) {
                let reference =
                    diffuse + specular * ring_average(bottom, top, 6, |theta| ggx_albedo(roughness, theta, REFERENCE));
                for d in cells {
                    let error = b.albedo(d, set).0 - reference;
                    if error.abs() > worst.abs() {
                        (worst, at) = (error, top.acos().to_degrees());
                    }
                }
            }
            eprintln!("{model:?} on {}: worst a(d) − reference = {worst:+.2e} (ring from {at:.1}°)", set.name());
            assert!(worst.abs() < 8e-3, "{model:?} on {}: {worst}", set.name());
        }
    }
}
