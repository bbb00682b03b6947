//! The stored transport matrix `G` of `docs/design.md` §3, in double precision (f64 values,
//! `usize` indices: 16 bytes per non-zero) or, with `--precision f32`, in single precision
//! (f32 values, u32 indices: 8 bytes per non-zero). Assembly and balancing always work in
//! double precision; the matrix is rounded once when stored. Every product accumulates in
//! f64, so single precision costs only the rounding of `G` (relative 6e-8 per entry).

use rayon::prelude::*;
use sprs::{CsMat, CsMatI, SpIndex};

/// Precision of the stored `G`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Precision {
    /// `f64` values (the default).
    #[default]
    Double,
    /// `f32` values with `u32` indices: 8 instead of 16 bytes per non-zero.
    Single,
}

impl Precision {
    /// `f64` or `f32`.
    pub fn parse(name: &str) -> Option<Precision> {
        match name {
            "f64" => Some(Precision::Double),
            "f32" => Some(Precision::Single),
            _ => None,
        }
    }

    /// `"f64"` or `"f32"`, as `--precision` names it.
    pub fn name(&self) -> &'static str {
        match self {
            Precision::Double => "f64",
            Precision::Single => "f32",
        }
    }
}

/// `G` as stored.
#[derive(Debug, Clone)]
pub enum TransportMatrix {
    /// Stored in double precision.
    Double(CsMat<f64>),
    /// Stored in single precision, `u32` indices.
    Single(CsMatI<f32, u32>),
}

impl TransportMatrix {
    /// `g` stored in `precision` (single precision needs fewer than 2³² non-zeros and
    /// rows; beyond that it stays double, which [`TransportMatrix::precision`] reports).
    pub fn new(g: CsMat<f64>, precision: Precision) -> TransportMatrix {
        if precision == Precision::Double || g.nnz() >= u32::MAX as usize || g.rows() >= u32::MAX as usize {
            return TransportMatrix::Double(g);
        }
        let shape = (g.rows(), g.cols());
        let indptr = g.indptr().raw_storage().iter().map(|&p| p as u32).collect();
        let indices = g.indices().iter().map(|&c| c as u32).collect();
        let data = g.data().iter().map(|&v| v as f32).collect();
        TransportMatrix::Single(CsMatI::new(shape, indptr, indices, data))
    }

    /// The precision the values are stored in.
    pub fn precision(&self) -> Precision {
        match self {
            TransportMatrix::Double(_) => Precision::Double,
            TransportMatrix::Single(_) => Precision::Single,
        }
    }

    /// Number of rows, `N·K`.
    pub fn rows(&self) -> usize {
        match self {
            TransportMatrix::Double(g) => g.rows(),
            TransportMatrix::Single(g) => g.rows(),
        }
    }

    /// Number of stored non-zeros.
    pub fn nnz(&self) -> usize {
        match self {
            TransportMatrix::Double(g) => g.nnz(),
            TransportMatrix::Single(g) => g.nnz(),
        }
    }

    /// Bytes of values, column indices and row pointers.
    pub fn bytes(&self) -> f64 {
        let (value, index) = match self {
            TransportMatrix::Double(_) => (8.0, std::mem::size_of::<usize>() as f64),
            TransportMatrix::Single(_) => (4.0, 4.0),
        };
        self.nnz() as f64 * (value + index) + (self.rows() + 1) as f64 * index
    }

    /// Non-zeros of row `r`.
    pub fn row_len(&self, r: usize) -> usize {
        match self {
            TransportMatrix::Double(g) => g.outer_view(r).map_or(0, |v| v.nnz()),
            TransportMatrix::Single(g) => g.outer_view(r).map_or(0, |v| v.nnz()),
        }
    }

    /// Calls `f(column, value)` for every stored entry of row `r`.
    #[inline]
    pub fn for_each_in_row(&self, r: usize, mut f: impl FnMut(usize, f64)) {
        match self {
            TransportMatrix::Double(g) => {
                if let Some(row) = g.outer_view(r) {
                    row.iter().for_each(|(c, &v)| f(c, v));
                }
            }
            TransportMatrix::Single(g) => {
                if let Some(row) = g.outer_view(r) {
                    row.iter().for_each(|(c, &v)| f(c, v as f64));
                }
            }
        }
    }

    /// `y = G x`, rows in parallel.
    pub fn apply(&self, x: &[f64], y: &mut [f64]) {
        match self {
            TransportMatrix::Double(g) => spmv(g, x, y),
            TransportMatrix::Single(g) => spmv(g, x, y),
        }
    }

    /// The double-precision matrix, when stored so.
    pub fn as_double(&self) -> Option<&CsMat<f64>> {
        match self {
            TransportMatrix::Double(g) => Some(g),
            TransportMatrix::Single(_) => None,
        }
    }
}

/// `y = A x` for CSR `A`, rows in parallel, accumulated in f64.
pub fn spmv<N: Copy + Into<f64> + Sync, I: SpIndex + Sync>(a: &CsMatI<N, I>, x: &[f64], y: &mut [f64]) {
    let (indptr, indices, data) = (a.indptr(), a.indices(), a.data());
    let indptr = indptr.raw_storage();
    y.par_iter_mut().enumerate().with_min_len(256).for_each(|(i, yi)| {
        let (lo, hi) = (indptr[i].index(), indptr[i + 1].index());
        *yi = indices[lo..hi].iter().zip(&data[lo..hi]).map(|(&j, &v)| v.into() * x[j.index()]).sum();
    });
}
