//! The `K × K` block of a material: the cell-averaged luminance factor `ρ̄(k,d)` of
//! `docs/design.md` §3 (`B`), with its optional transmission block, albedo and application.

use crate::directions::DirectionSet;
use std::f64::consts::PI;

/// The `K × K` blocks of one material, row-major (row = outgoing cell `k`).
#[derive(Debug, Clone, PartialEq)]
pub struct Block {
    k: usize,
    reflect: Vec<f64>,
    transmit: Option<Vec<f64>>,
}

impl Block {
    /// A block from its row-major reflection values and optional transmission values.
    pub fn new(k: usize, reflect: Vec<f64>, transmit: Option<Vec<f64>>) -> Block {
        Block { k, reflect, transmit }
    }

    /// The number of cells `K` (the block is `K × K`).
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

    /// True when the material transmits (the block has `τ̄`).
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

    /// `y = ρ̄ᵀ x`: the transpose of [`Block::apply`] (the light arriving in each cell `d`
    /// weighed by what the outgoing cells ask of it).
    pub fn apply_transposed(&self, x: &[f64], y: &mut [f64]) {
        transposed_mat_vec(&self.reflect, self.k, x, y, false);
    }

    /// `y += τ̄ᵀ x`, the transpose of [`Block::apply_transmit`], when the material transmits.
    pub fn apply_transmit_transposed(&self, x: &[f64], y: &mut [f64]) {
        if let Some(t) = &self.transmit {
            transposed_mat_vec(t, self.k, x, y, true);
        }
    }

    /// True when no reflection or transmission value is negative (every block a material
    /// model builds; a kernel file's may not be).
    pub fn is_nonnegative(&self) -> bool {
        self.reflect.iter().chain(self.transmit.iter().flatten()).all(|&v| v >= 0.0)
    }
}

#[inline]
fn mat_vec(values: &[f64], k: usize, x: &[f64], y: &mut [f64], add: bool) {
    for (row, yk) in values.chunks_exact(k).zip(y.iter_mut()) {
        let v: f64 = row.iter().zip(x).map(|(a, b)| a * b).sum();
        *yk = if add { *yk + v } else { v };
    }
}

fn transposed_mat_vec(values: &[f64], k: usize, x: &[f64], y: &mut [f64], add: bool) {
    if !add {
        y.fill(0.0);
    }
    for (row, xk) in values.chunks_exact(k).zip(x) {
        y.iter_mut().zip(row).for_each(|(yd, a)| *yd += a * xk);
    }
}
