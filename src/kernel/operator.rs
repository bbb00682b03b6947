//! The kernel as an operator: `K = B·G`, applied factored (`G` then `B`) or formed
//! explicitly as one sparse matrix (`design.md` §3).
//!
//! Every solver sees only [`LinOp`]; the factored form never builds the product, the
//! explicit one is there for norms, direct solves and export.

use crate::brdf::Block;
use crate::directions::DirectionSet;
use rayon::prelude::*;
use sprs::{CsMat, TriMat};

/// A square linear operator `y = A x`.
pub trait LinOp: Sync {
    fn dim(&self) -> usize;
    fn apply(&self, x: &[f64], y: &mut [f64]);
}

/// `K = B·G`: transport `G` over `(patch, cell)` unknowns and per-material blocks `B`.
#[derive(Debug, Clone)]
pub struct Kernel {
    pub g: CsMat<f64>,
    pub directions: DirectionSet,
    /// One block per material.
    pub blocks: Vec<Block>,
    /// Material of each patch.
    pub patch_material: Vec<u32>,
}

impl Kernel {
    /// Number of patches `N`.
    pub fn patches(&self) -> usize {
        self.patch_material.len()
    }

    /// Number of direction cells `K`.
    pub fn cells(&self) -> usize {
        self.directions.len()
    }

    /// `y = G x`, parallel over rows.
    pub fn apply_transport(&self, x: &[f64], y: &mut [f64]) {
        spmv(&self.g, x, y);
    }

    /// `y = B z`, block by block.
    pub fn apply_materials(&self, z: &[f64], y: &mut [f64]) {
        let k = self.cells();
        y.par_chunks_mut(k).zip(z.par_chunks(k)).zip(self.patch_material.par_iter()).for_each(|((yi, zi), &m)| {
            self.blocks[m as usize].apply(zi, yi);
        });
    }

    /// The explicit product `B·G` as one sparse matrix.
    pub fn explicit(&self) -> CsMat<f64> {
        let k = self.cells();
        let n = self.g.rows();
        let mut tri = TriMat::with_capacity((n, n), self.g.nnz() * k);
        for (row, vec) in self.g.outer_iterator().enumerate() {
            let (i, d) = (row / k, row % k);
            let block = &self.blocks[self.patch_material[i] as usize];
            for (col, &value) in vec.iter() {
                for out in 0..k {
                    let b = block.at(out, d);
                    if b != 0.0 {
                        tri.add_triplet(i * k + out, col, b * value);
                    }
                }
            }
        }
        tri.to_csr()
    }
}

/// The factored operator: `K x = B (G x)`, never forming the product.
pub struct Factored<'a> {
    kernel: &'a Kernel,
    scratch: std::sync::Mutex<Vec<f64>>,
}

impl<'a> Factored<'a> {
    pub fn new(kernel: &'a Kernel) -> Self {
        Factored { kernel, scratch: std::sync::Mutex::new(vec![0.0; kernel.g.rows()]) }
    }
}

impl LinOp for Factored<'_> {
    fn dim(&self) -> usize {
        self.kernel.g.rows()
    }

    fn apply(&self, x: &[f64], y: &mut [f64]) {
        let mut z = self.scratch.lock().unwrap_or_else(|e| e.into_inner());
        self.kernel.apply_transport(x, &mut z);
        self.kernel.apply_materials(&z, y);
    }
}

/// An explicit sparse matrix as an operator.
pub struct Explicit(pub CsMat<f64>);

impl LinOp for Explicit {
    fn dim(&self) -> usize {
        self.0.rows()
    }

    fn apply(&self, x: &[f64], y: &mut [f64]) {
        spmv(&self.0, x, y);
    }
}

/// `y = A x` for CSR `A`, rows in parallel.
pub fn spmv(a: &CsMat<f64>, x: &[f64], y: &mut [f64]) {
    let (indptr, indices, data) = (a.indptr(), a.indices(), a.data());
    let indptr = indptr.raw_storage();
    y.par_iter_mut().enumerate().with_min_len(256).for_each(|(i, yi)| {
        let (lo, hi) = (indptr[i], indptr[i + 1]);
        *yi = indices[lo..hi].iter().zip(&data[lo..hi]).map(|(&j, &v)| v * x[j]).sum();
    });
}
