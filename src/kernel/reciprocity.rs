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

use super::operator::Kernel;
use std::f64::consts::PI;

/// `s_jm` for every column `(j, m)`, flat `j·K + m`, of `kernel` over patches of `areas`.
pub fn sent_shares(kernel: &Kernel, areas: &[f64]) -> Vec<f64> {
    let k = kernel.cells();
    let rows: Vec<f64> = (0..kernel.g.rows()).map(|row| areas[row / k]).collect();
    let mut received = vec![0.0; rows.len()];
    kernel.g.leaving(&rows, &mut received);
    let cells = kernel.directions.cells();
    received
        .iter()
        .enumerate()
        .map(|(column, r)| {
            let sent = areas[column / k] * cells[column % k].projected;
            if sent > 0.0 { PI * r / sent } else { 1.0 }
        })
        .collect()
}
