//! Ideal mirror: `ρ(l,l') = π ρ_s δ(l − R l')/cosθ'`, so each incoming direction's whole
//! reflected energy lands in the cell of its mirror image:
//! `ρ̄(k,d) = π ρ_s μ(C_d ∩ R C_k) / (μ_k μ_d)`, computed by stratified quadrature of `C_d`.

use super::cells::{Accumulator, mirror, stratified};
use crate::directions::DirectionSet;
use std::f64::consts::PI;

/// Incoming directions per cell are `STRATA²`.
const STRATA: usize = 32;

pub fn block(reflectance: f64, directions: &DirectionSet) -> Vec<f64> {
    let mut acc = Accumulator::new(directions.len());
    for d in 0..directions.len() {
        for (l, w) in stratified(directions, d, STRATA) {
            acc.add(directions.lookup(mirror(l)), d, PI * reflectance * w);
        }
    }
    acc.finish(directions)
}
