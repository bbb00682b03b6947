//! Ideal mirror: `ρ(l,l') = π ρ_s δ(l − R l')/cosθ'`, so each incoming direction's whole
//! reflected energy lands in the cell of its mirror image:
//! `ρ̄(k,d) = π ρ_s μ(C_d ∩ R C_k) / (μ_k μ_d)`, computed by stratified quadrature of `C_d`.
//! Sampled deterministically: the mirror direction with weight `ρ_s` (a delta, which no
//! light source can be sampled towards).
//!
//! ```toml
//! [[material]]
//! name = "mirror"
//! type = "mirror"
//! reflectance = 0.75    # required, in [0, 1]
//! ```

use super::cells::{Accumulator, mirror, stratified};
use super::sample::Sample;
use crate::directions::DirectionSet;
use glam::DVec3;
use std::f64::consts::PI;

/// The `type` that selects this model and the keys it takes.
pub const TYPE: &str = "mirror";
/// The keys of `[[material]]` it takes besides `name` and `type`.
pub const KEYS: &[&str] = &["reflectance"];

/// Incoming directions per cell are `STRATA²`.
const STRATA: usize = 32;

/// The row-major `K × K` block `ρ̄(k, d)` of a mirror of specular reflectance
/// `reflectance` on `directions`.
pub fn block(reflectance: f64, directions: &DirectionSet) -> Vec<f64> {
    let mut acc = Accumulator::new(directions.len());
    for d in 0..directions.len() {
        for (l, w) in stratified(directions, d, STRATA) {
            acc.add(directions.lookup(mirror(l)), d, PI * reflectance * w);
        }
    }
    acc.finish(directions)
}

/// The mirror image of `l` with weight `ρ_s`; `None` for a black mirror.
pub fn sample(reflectance: f64, l: DVec3) -> Option<Sample> {
    let direction = mirror(l);
    (reflectance > 0.0).then_some(Sample { direction, weight: reflectance, pdf: 0.0, delta: true })
}
