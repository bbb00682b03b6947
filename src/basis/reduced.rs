//! The kernel in a factored angular basis: the system `c = s + K̃ c` for the `N·M`
//! coefficients of `L = L0 + Ψ c`, with `K̃ = Φᵀ G Ψ` and `s = Φᵀ G L0` (`factor.rs`,
//! `docs/design.md` §4). Applied matrix-free (expand with `Ψ`, transport with `G`, contract
//! with `Φᵀ`) for the iterative methods, or assembled with dense `M × M` blocks per pair
//! of linked patches for the direct and Gauss–Seidel methods.

use super::Factorization;
use crate::geometry::NO_TWIN;
use crate::kernel::{Footprint, Kernel, TooLarge};
use crate::solve::LinOp;
use rayon::prelude::*;
use sprs::CsMat;
use std::collections::BTreeMap;
use std::sync::Mutex;

/// `K̃ = Φᵀ G Ψ` over the coefficients of every patch.
pub struct Reduced<'a> {
    kernel: &'a Kernel,
    factors: &'a Factorization,
    /// `Ψ c` and `G Ψ c`, reused between applications.
    scratch: Mutex<(Vec<f64>, Vec<f64>)>,
}

impl<'a> Reduced<'a> {
    /// The reduced operator of `kernel` in the basis of `factors`.
    pub fn new(kernel: &'a Kernel, factors: &'a Factorization) -> Self {
        let cells = kernel.g.rows();
        Reduced { kernel, factors, scratch: Mutex::new((vec![0.0; cells], vec![0.0; cells])) }
    }

    /// `s = Φᵀ G L0`.
    pub fn source(&self, l0: &[f64]) -> Vec<f64> {
        let mut arriving = vec![0.0; l0.len()];
        self.kernel.apply_transport(l0, &mut arriving);
        let mut s = vec![0.0; self.dim()];
        self.contract(&arriving, &mut s);
        s
    }

    /// The luminance field `L0 + Ψ c`, `x[i·K + k]`.
    pub fn field(&self, l0: &[f64], c: &[f64]) -> Vec<f64> {
        let mut x = vec![0.0; l0.len()];
        self.expand(c, &mut x);
        x.iter_mut().zip(l0).for_each(|(x, l)| *x += l);
        x
    }

    /// `y = Ψ c` patch by patch.
    fn expand(&self, c: &[f64], y: &mut [f64]) {
        let (k, m) = (self.factors.k, self.factors.m);
        y.par_chunks_mut(k).enumerate().for_each(|(i, yi)| {
            let psi = &self.factors.materials[self.kernel.patch_material[i] as usize].psi;
            let ci = &c[i * m..(i + 1) * m];
            for (row, v) in psi.chunks_exact(m).zip(yi.iter_mut()) {
                *v = row.iter().zip(ci).map(|(a, b)| a * b).sum();
            }
        });
    }

    /// `c = Φᵀ z`: the front factor on what arrives at the patch, the back factor on
    /// what arrives at its twin.
    fn contract(&self, z: &[f64], c: &mut [f64]) {
        let (k, m) = (self.factors.k, self.factors.m);
        c.par_chunks_mut(m).enumerate().for_each(|(i, ci)| {
            let f = &self.factors.materials[self.kernel.patch_material[i] as usize];
            ci.fill(0.0);
            let mut add = |phi: &[f64], zj: &[f64]| {
                for (row, zd) in phi.chunks_exact(m).zip(zj) {
                    ci.iter_mut().zip(row).for_each(|(c, p)| *c += p * zd);
                }
            };
            add(&f.front, &z[i * k..(i + 1) * k]);
            let twin = self.kernel.twin[i];
            if let (Some(back), true) = (&f.back, twin != NO_TWIN) {
                add(back, &z[twin as usize * k..(twin as usize + 1) * k]);
            }
        });
    }

    /// Non-zeros of the assembled `K̃`: `M²` per linked pair of patches.
    pub fn explicit_nonzeros(&self) -> f64 {
        let pairs: usize = (0..self.kernel.patches()).into_par_iter().map(|i| self.partners(i).len()).sum();
        pairs as f64 * (self.factors.m * self.factors.m) as f64
    }

    /// The patches whose light reaches patch `i` (through `G` at `i` or at its twin).
    fn partners(&self, i: usize) -> Vec<u32> {
        let k = self.factors.k;
        let mut rows = vec![i];
        let twin = self.kernel.twin[i];
        if twin != NO_TWIN && self.factors.materials[self.kernel.patch_material[i] as usize].back.is_some() {
            rows.push(twin as usize);
        }
        let mut js: Vec<u32> = Vec::new();
        for row in rows.iter().flat_map(|&r| r * k..(r + 1) * k) {
            self.kernel.g.for_each_in_row(row, |col, _| js.push((col / k) as u32));
        }
        js.sort_unstable();
        js.dedup();
        js
    }

    /// `K̃` as one sparse matrix with dense `M × M` blocks, refused (with the estimate)
    /// over `limit` bytes.
    pub fn explicit(&self, limit: u64) -> Result<CsMat<f64>, TooLarge> {
        let (k, m) = (self.factors.k, self.factors.m);
        let nonzeros = self.explicit_nonzeros();
        let bytes = nonzeros * crate::kernel::memory::BYTES_PER_NONZERO as f64;
        let (what, patches) = ("reduced kernel Φᵀ G Ψ", self.kernel.patches());
        Footprint { what, bytes, nonzeros, patches, cells: m }.check(limit)?;
        let n = self.kernel.patches();
        // Block row i: for each partner j, the M × M block Σ_d Σ_m Φ_i[d,·] G[(i,d),(j,m)] Ψ_j[m,·].
        let rows: Vec<BTreeMap<u32, Vec<f64>>> = (0..n)
            .into_par_iter()
            .map(|i| {
                let f = &self.factors.materials[self.kernel.patch_material[i] as usize];
                let mut blocks: BTreeMap<u32, Vec<f64>> = BTreeMap::new();
                let mut add = |phi: &[f64], r: usize| {
                    for d in 0..k {
                        let phi_d = &phi[d * m..(d + 1) * m];
                        self.kernel.g.for_each_in_row(r * k + d, |col, g| {
                            let (j, cell) = (col / k, col % k);
                            let psi = &self.factors.materials[self.kernel.patch_material[j] as usize].psi;
                            let psi_m = &psi[cell * m..(cell + 1) * m];
                            let block = blocks.entry(j as u32).or_insert_with(|| vec![0.0; m * m]);
                            for (a, p) in phi_d.iter().enumerate() {
                                let pg = p * g;
                                block[a * m..(a + 1) * m].iter_mut().zip(psi_m).for_each(|(b, s)| *b += pg * s);
                            }
                        });
                    }
                };
                add(&f.front, i);
                let twin = self.kernel.twin[i];
                if let (Some(back), true) = (&f.back, twin != NO_TWIN) {
                    add(back, twin as usize);
                }
                blocks
            })
            .collect();
        let mut indptr = Vec::with_capacity(n * m + 1);
        let (mut indices, mut data) = (Vec::with_capacity(nonzeros as usize), Vec::with_capacity(nonzeros as usize));
        indptr.push(0);
        for blocks in &rows {
            for a in 0..m {
                for (&j, block) in blocks {
                    for b in 0..m {
                        indices.push(j as usize * m + b);
                        data.push(block[a * m + b]);
                    }
                }
                indptr.push(indices.len());
            }
        }
        Ok(CsMat::new((n * m, n * m), indptr, indices, data))
    }
}

impl LinOp for Reduced<'_> {
    fn dim(&self) -> usize {
        self.kernel.patches() * self.factors.m
    }

    fn apply(&self, c: &[f64], y: &mut [f64]) {
        let mut guard = self.scratch.lock().unwrap_or_else(|e| e.into_inner());
        let (expanded, arriving) = &mut *guard;
        self.expand(c, expanded);
        self.kernel.apply_transport(expanded, arriving);
        self.contract(arriving, y);
    }
}
