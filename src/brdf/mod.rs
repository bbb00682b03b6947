//! Materials as cell-averaged luminance factors: the blocks of `B` (`design.md` §1, §3).
//!
//! `ρ̄(k,d) = (1/μ_d) ∫_{C_d} ρ(l_k, l') cosθ' dω'` for outgoing cell `k` and incoming
//! cell `d`. A block is shared by every patch of one material (isotropic models in local
//! frames). Materials never see the scene file: they get a [`MaterialModel`].

use crate::directions::DirectionSet;
use crate::scene::MaterialModel;

/// A `K × K` block `ρ̄(k,d)`, row-major (row = outgoing cell `k`).
#[derive(Debug, Clone, PartialEq)]
pub struct Block {
    k: usize,
    values: Vec<f64>,
}

impl Block {
    /// The cell-averaged luminance factor of `model` on `directions`.
    pub fn of(model: &MaterialModel, directions: &DirectionSet) -> Block {
        let k = directions.len();
        let values = match model {
            MaterialModel::Lambert { reflectance } => vec![*reflectance; k * k],
        };
        Block { k, values }
    }

    pub fn size(&self) -> usize {
        self.k
    }

    /// `ρ̄(k, d)`.
    pub fn at(&self, k: usize, d: usize) -> f64 {
        self.values[k * self.k + d]
    }

    /// Row-major values.
    pub fn values(&self) -> &[f64] {
        &self.values
    }

    /// Directional-hemispherical reflectance for light arriving in cell `d`:
    /// `a(d) = (1/π) Σ_k ρ̄(k,d) μ_k`.
    pub fn albedo(&self, d: usize, directions: &DirectionSet) -> f64 {
        let cells = directions.cells();
        (0..self.k).map(|k| self.at(k, d) * cells[k].projected).sum::<f64>() / std::f64::consts::PI
    }

    /// `y = ρ̄ x` for one patch's `K` values.
    #[inline]
    pub fn apply(&self, x: &[f64], y: &mut [f64]) {
        for (k, yk) in y.iter_mut().enumerate() {
            let row = &self.values[k * self.k..(k + 1) * self.k];
            *yk = row.iter().zip(x).map(|(a, b)| a * b).sum();
        }
    }
}
