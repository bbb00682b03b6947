//! Illuminance of the patches, lx: `E_i = π Σ_d ((G x)(i,d) + D(i,d))` (`docs/design.md` §1,
//! §3), the light arriving from the surfaces (`G x`, the transport of the solved field)
//! plus the luminaires' direct light `D`, both per incoming cell `d` in the units of `G x`.
//! The one place this sum is formed; probes and grids gather at exact points instead.

use crate::model::Model;
use std::f64::consts::PI;

/// The light arriving at every (patch, cell), `(G x)(i,d) + D(i,d)`, flat `i·K + d`.
pub fn arriving(model: &Model, x: &[f64]) -> Vec<f64> {
    let mut light = vec![0.0; x.len()];
    model.kernel.apply_transport(x, &mut light);
    light.iter_mut().zip(&model.direct.arriving).for_each(|(l, d)| *l += d);
    light
}

/// `E_i = π Σ_d a(i,d)` of the light `a` arriving per (patch, cell) with `cells` cells, lx.
pub fn patch_illuminance(arriving: &[f64], cells: usize) -> Vec<f64> {
    arriving.chunks(cells).map(|c| PI * c.iter().sum::<f64>()).collect()
}
