//! `G` as the kernel applies it (`docs/design.md` §3 and §3b): every facing pair of patches
//! stored (the uniform kernel) or the hierarchy's links applied on its leaves by pull,
//! gather and push. Solvers, readouts and `K = B·G` see one `rows` and one `apply`; what
//! needs the stored entries asks for them and is told when there are none.

use super::hierarchy::Operator;
use super::uniform::{Precision, TransportMatrix};
use sprs::CsMat;

/// The transport operator `G` over `(patch, cell)` unknowns.
pub enum Transport {
    /// Assembled pair by pair over the uniform mesh (`docs/design.md` §3).
    Uniform(TransportMatrix),
    /// Links of the hierarchical kernel between nodes above the leaves (`docs/design.md` §3b).
    Hierarchical(Box<Operator>),
}

impl Transport {
    /// Unknowns `N·K`.
    pub fn rows(&self) -> usize {
        match self {
            Transport::Uniform(g) => g.rows(),
            Transport::Hierarchical(h) => h.dim(),
        }
    }

    /// `y = G x`.
    pub fn apply(&self, x: &[f64], y: &mut [f64]) {
        match self {
            Transport::Uniform(g) => g.apply(x, y),
            Transport::Hierarchical(h) => h.arriving(x, y),
        }
    }

    /// `x = Gᵀ y`: what each column receives, the rows weighed by `y` (serial: it scatters).
    /// The hierarchy runs its links backwards (`hierarchy/transpose.rs`) without the
    /// expansion.
    pub fn leaving(&self, y: &[f64], x: &mut [f64]) {
        match self {
            Transport::Uniform(g) => {
                x.fill(0.0);
                for (row, &w) in y.iter().enumerate() {
                    g.for_each_in_row(row, |column, value| x[column] += w * value);
                }
            }
            Transport::Hierarchical(h) => h.leaving(y, x),
        }
    }

    /// Entries of row `r` written out (the hierarchy's expansion, `hierarchy/expand.rs`).
    pub fn row_len(&self, r: usize) -> usize {
        match self {
            Transport::Uniform(g) => g.row_len(r),
            Transport::Hierarchical(h) => h.row_len(r),
        }
    }

    /// Calls `f(column, value)` for every entry of row `r` written out (a column may come
    /// twice from the hierarchy; sum them).
    #[inline]
    pub fn for_each_in_row(&self, r: usize, f: impl FnMut(usize, f64)) {
        match self {
            Transport::Uniform(g) => g.for_each_in_row(r, f),
            Transport::Hierarchical(h) => h.for_each_in_row(r, f),
        }
    }

    /// Stored entries: the matrix's non-zeros, or the pieces of the hierarchy's links.
    pub fn nnz(&self) -> usize {
        match self {
            Transport::Uniform(g) => g.nnz(),
            Transport::Hierarchical(h) => h.pieces(),
        }
    }

    /// Bytes held.
    pub fn bytes(&self) -> f64 {
        match self {
            Transport::Uniform(g) => g.bytes(),
            Transport::Hierarchical(h) => h.bytes(),
        }
    }

    /// The stored matrix of the uniform kernel; `None` for the hierarchy.
    pub fn matrix(&self) -> Option<&TransportMatrix> {
        match self {
            Transport::Uniform(g) => Some(g),
            Transport::Hierarchical(_) => None,
        }
    }

    /// The hierarchy's operator; `None` for the uniform kernel.
    pub fn hierarchy(&self) -> Option<&Operator> {
        match self {
            Transport::Uniform(_) => None,
            Transport::Hierarchical(h) => Some(h),
        }
    }

    /// The double-precision matrix of the uniform kernel.
    pub fn as_double(&self) -> Option<&CsMat<f64>> {
        self.matrix().and_then(TransportMatrix::as_double)
    }

    /// Precision of the stored values (the hierarchy's are double).
    pub fn precision(&self) -> Precision {
        self.matrix().map_or(Precision::Double, TransportMatrix::precision)
    }
}
