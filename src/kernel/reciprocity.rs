//! The kernel's closure seen from the sender (`docs/design.md` §3): for every column `(j, m)` of
//! `G`, the share of the light it sends that the rows receive,
//! `s_jm = π Σ_(i,d) A_i G[(i,d),(j,m)] / (A_j μ_m)`.
//!
//! For an exactly reciprocal `G` (`A_i G_ij = A_j G_ji`) this is the row closure of `(j, m)`,
//! and in a closed scene it is 1. The energy balance's light escaping from the surfaces is
//! exactly `Σ_(j,m) Φ_jm (1 − s_jm)` with `Φ_jm = A_j μ_m x_jm` the outgoing flux
//! (`readout::energy`): where `s` differs from 1 in a closed scene, the difference is the
//! discretization error of the balance, and weighted by the solved field it bounds it.
//! One transposed application `Gᵀ A` gives every column at once.
//!
//! With plane mirrors carried by images (`docs/design.md` (3.10)), the light of `(j, m)`
//! that lands on a mirror `M` arrives once on `M`'s rows and again, times `ρ_M`, through
//! the images, while `M`'s own columns send nothing. The shares count it once: `s_jm` less
//! `ρ_M` times the share landing on `M`, and 1 for `M`'s columns (their light is the images').
//! The escaped flux is still `Σ Φ (1 − s)`, since `M` sends `ρ_M` times what it receives.

use super::operator::Kernel;
use crate::transfer::image::PlaneMirror;
use std::f64::consts::PI;

/// `s_jm` for every column `(j, m)`, flat `j·K + m`, of `kernel` over patches of `areas`,
/// whose light by way of `mirrors` is carried by their images.
pub fn sent_shares(kernel: &Kernel, areas: &[f64], mirrors: &[PlaneMirror]) -> Vec<f64> {
    let k = kernel.cells();
    let mut reflectance = vec![None; areas.len()];
    for m in mirrors {
        m.patches.iter().for_each(|&p| reflectance[p as usize] = Some(m.reflectance));
    }
    let rows: Vec<f64> = (0..kernel.g.rows()).map(|row| areas[row / k]).collect();
    let mut received = vec![0.0; rows.len()];
    kernel.g.leaving(&rows, &mut received);
    if !mirrors.is_empty() {
        let reflected: Vec<f64> = (0..rows.len()).map(|row| rows[row] * reflectance[row / k].unwrap_or(0.0)).collect();
        let mut again = vec![0.0; rows.len()];
        kernel.g.leaving(&reflected, &mut again);
        received.iter_mut().zip(&again).for_each(|(r, a)| *r -= a);
    }
    let cells = kernel.directions.cells();
    received
        .iter()
        .enumerate()
        .map(|(column, r)| {
            let sent = areas[column / k] * cells[column % k].projected;
            if sent > 0.0 && reflectance[column / k].is_none() { PI * r / sent } else { 1.0 }
        })
        .collect()
}
