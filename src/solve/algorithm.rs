//! [`Algorithm`]: what a solve ran, as [`SolveInfo`](super::SolveInfo) records it and the
//! output names it (the summary's solve line, the solution file's `method` attribute). It
//! is not the [`Method`](super::Method) asked for: `direct` runs a dense or a sparse LU by
//! size, and a zero source or a start within the tolerance runs nothing.

use std::fmt;

/// The algorithm a solve ran.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Algorithm {
    /// Nothing: the source term is zero, so the solution is `x = 0`.
    ZeroSource,
    /// Successive approximation (reflection orders).
    SuccessiveApproximation,
    /// Gauss–Seidel sweeps.
    GaussSeidel,
    /// Southwell's progressive refinement.
    Southwell,
    /// Restarted GMRES.
    Gmres,
    /// BiCGSTAB.
    Bicgstab,
    /// Dense LU of `I − K`.
    DenseLu,
    /// Sparse LU of `I − K`.
    SparseLu,
    /// No iteration: the start projected from known solutions met the tolerance.
    Projection,
}

impl Algorithm {
    /// Its name as printed and written.
    pub fn name(self) -> &'static str {
        match self {
            Algorithm::ZeroSource => "none (zero source)",
            Algorithm::SuccessiveApproximation => "successive approximation",
            Algorithm::GaussSeidel => "Gauss-Seidel",
            Algorithm::Southwell => "Southwell",
            Algorithm::Gmres => "GMRES",
            Algorithm::Bicgstab => "BiCGSTAB",
            Algorithm::DenseLu => "direct (dense LU)",
            Algorithm::SparseLu => "direct (sparse LU)",
            Algorithm::Projection => "projection",
        }
    }
}

impl fmt::Display for Algorithm {
    fn fmt(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str(self.name())
    }
}
