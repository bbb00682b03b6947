//! Materials as cell-averaged luminance factors: the blocks of `B` (`design.md` §1, §3).
//!
//! A block holds, for outgoing cell `k` and incoming cell `d`, the luminance factor
//! averaged over both cells with the projected-solid-angle measure,
//!
//! `ρ̄(k,d) = (1/(μ_k μ_d)) ∫_{C_k} ∫_{C_d} ρ(l, l') cosθ cosθ' dω' dω`,
//!
//! which keeps reciprocity (`ρ̄(k,d) = ρ̄(d,k)` when `ρ(l,l') = ρ(l',l)`) and energy: the
//! albedo of incoming cell `d`, `a(d) = (1/π) Σ_k ρ̄(k,d) μ_k`, is the cos-weighted mean
//! over the cell of the directional-hemispherical reflectance. A transmitting material
//! has a second block for light arriving on the other side of a two-sided surface
//! (incoming cell in the back patch's frame). Blocks are shared by every patch of one
//! material (isotropic models in local frames). Materials never see the scene file.
//! The continuous models' formulas and lobe samplers (`phong`, `ggx`) are public: the Monte
//! Carlo estimators of `crate::trace` use them.

mod cells;
pub mod ggx;
mod lambert;
mod mirror;
pub mod phong;

pub use cells::mirror as mirror_image;

use crate::directions::DirectionSet;
use crate::scene::MaterialModel;
use std::f64::consts::PI;

/// The `K × K` blocks of one material, row-major (row = outgoing cell `k`).
#[derive(Debug, Clone, PartialEq)]
pub struct Block {
    k: usize,
    reflect: Vec<f64>,
    transmit: Option<Vec<f64>>,
}

impl Block {
    /// The cell-averaged luminance factor of `model` on `directions`.
    pub fn of(model: &MaterialModel, directions: &DirectionSet) -> Block {
        let k = directions.len();
        let (reflect, transmit) = match *model {
            MaterialModel::Lambert { reflectance, transmittance } => {
                (lambert::block(reflectance, k), (transmittance > 0.0).then(|| lambert::block(transmittance, k)))
            }
            MaterialModel::Phong { diffuse, specular, exponent } => {
                (phong::block(diffuse, specular, exponent, directions), None)
            }
            MaterialModel::Mirror { reflectance } => (mirror::block(reflectance, directions), None),
            MaterialModel::Ggx { diffuse, specular, roughness } => {
                (ggx::block(diffuse, specular, roughness, directions), None)
            }
        };
        Block { k, reflect, transmit }
    }

    pub fn size(&self) -> usize {
        self.k
    }

    /// `ρ̄(k, d)` of reflection.
    pub fn at(&self, k: usize, d: usize) -> f64 {
        self.reflect[k * self.k + d]
    }

    /// `τ̄(k, d)` of transmission, when the material transmits.
    pub fn transmit_at(&self, k: usize, d: usize) -> Option<f64> {
        self.transmit.as_ref().map(|t| t[k * self.k + d])
    }

    pub fn transmits(&self) -> bool {
        self.transmit.is_some()
    }

    /// Row-major reflection values.
    pub fn values(&self) -> &[f64] {
        &self.reflect
    }

    /// Row-major transmission values.
    pub fn transmit_values(&self) -> Option<&[f64]> {
        self.transmit.as_deref()
    }

    /// Fraction of the light arriving in cell `d` that is reflected (`a(d)`) and, for a
    /// transmitter, transmitted: `(1/π) Σ_k ρ̄(k,d) μ_k`.
    pub fn albedo(&self, d: usize, directions: &DirectionSet) -> (f64, f64) {
        let cells = directions.cells();
        let sum = |v: &[f64]| (0..self.k).map(|k| v[k * self.k + d] * cells[k].projected).sum::<f64>() / PI;
        (sum(&self.reflect), self.transmit.as_deref().map_or(0.0, sum))
    }

    /// `y = ρ̄ x` for one patch's `K` values.
    #[inline]
    pub fn apply(&self, x: &[f64], y: &mut [f64]) {
        mat_vec(&self.reflect, self.k, x, y, false);
    }

    /// `y += τ̄ x` (light arriving at the back patch), when the material transmits.
    #[inline]
    pub fn apply_transmit(&self, x: &[f64], y: &mut [f64]) {
        if let Some(t) = &self.transmit {
            mat_vec(t, self.k, x, y, true);
        }
    }
}

#[inline]
fn mat_vec(values: &[f64], k: usize, x: &[f64], y: &mut [f64], add: bool) {
    for (row, yk) in values.chunks_exact(k).zip(y.iter_mut()) {
        let v: f64 = row.iter().zip(x).map(|(a, b)| a * b).sum();
        *yk = if add { *yk + v } else { v };
    }
}
