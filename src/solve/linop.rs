//! The one operator trait every solver takes (`docs/design.md` §4): `y = A x` on a flat vector.
//! The solvers own it (as in faer); the kernel's operators are adapted here, so the kernel
//! floor knows nothing of solvers.

use crate::kernel::{Explicit, Factored};

/// A square linear operator `y = A x`.
pub trait LinOp: Sync {
    /// Number of unknowns (rows and columns of `A`).
    fn dim(&self) -> usize;
    /// `y = A x`; `x` and `y` have length [`LinOp::dim`].
    fn apply(&self, x: &[f64], y: &mut [f64]);
}

impl LinOp for Factored<'_> {
    fn dim(&self) -> usize {
        Factored::dim(self)
    }

    fn apply(&self, x: &[f64], y: &mut [f64]) {
        Factored::apply(self, x, y);
    }
}

impl LinOp for Explicit {
    fn dim(&self) -> usize {
        Explicit::dim(self)
    }

    fn apply(&self, x: &[f64], y: &mut [f64]) {
        Explicit::apply(self, x, y);
    }
}
