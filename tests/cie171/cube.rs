//! 5.8, internal reflected component: an isotropic 10 000 lm source in a closed 4 m cube
//! of reflectance ρ; the area-averaged indirect illuminance `ρΦ/(S_T(1 − ρ))` for every ρ
//! of Table 20, up to 0.95, solved by LU. Reflection orders alone fall short at high ρ.

use super::{compare, solve_model, solved};
use std::f64::consts::PI;
use ugo::kernel::Factored;
use ugo::material::MaterialModel;
use ugo::readout::illuminance::patch_illuminance;
use ugo::solve::Method;
use ugo::solve::orders::reflection_orders;

/// CIE 171:2006 Table 20: ρ and the average indirect illuminance, lx.
const TABLE_20: [(f64, f64); 11] = [
    (0.05, 5.48),
    (0.10, 11.6),
    (0.20, 26.0),
    (0.30, 44.6),
    (0.40, 69.4),
    (0.50, 104.0),
    (0.60, 156.0),
    (0.70, 243.0),
    (0.80, 417.0),
    (0.90, 937.0),
    (0.95, 1979.0),
];

#[test]
fn cie_5_8_interreflection_in_a_cube_up_to_rho_0_95() {
    let mut s = solved("5.8-interreflection");
    let model = &mut s.model;
    let area: f64 = model.mesh.patches.iter().map(|p| p.area).sum();
    let direct: f64 = model
        .mesh
        .patches
        .iter()
        .zip(patch_illuminance(&model.direct.arriving, 1))
        .map(|(p, e)| p.area * e)
        .sum::<f64>()
        / area;
    compare("5.8", &[("E_dir,avg", 104.17, direct)]);
    let indirect = |model: &ugo::model::Model, x: &[f64]| {
        let mut gx = vec![0.0; x.len()];
        model.kernel.apply_transport(x, &mut gx);
        model.mesh.patches.iter().zip(&gx).map(|(p, g)| p.area * PI * g).sum::<f64>() / area
    };
    let mut rows = Vec::new();
    let labels: Vec<String> = TABLE_20.iter().map(|(rho, _)| format!("ρ = {rho:.2}")).collect();
    for (&(rho, reference), label) in TABLE_20.iter().zip(&labels) {
        let material = MaterialModel::Lambert { reflectance: rho, transmittance: 0.0 };
        model.kernel.blocks[0] = material.block(&model.kernel.directions);
        model.l0 = model.source_term();
        let x = solve_model(model, Method::Direct);
        rows.push((label.as_str(), reference, indirect(model, &x)));
        if rho == 0.95 {
            let orders = reflection_orders(&Factored::new(&model.kernel), &model.l0, &[4, 64]);
            for (n, partial) in &orders.partial_sums {
                let short = indirect(model, partial) / indirect(model, &x) - 1.0;
                eprintln!(
                    "5.8 at ρ = 0.95: after {n} reflection orders the average falls short by {:.1} %",
                    -100.0 * short
                );
                assert!(short < -0.02, "bounce-limited sums fail at high ρ: {short}");
            }
        }
    }
    compare("5.8", &rows);
}
