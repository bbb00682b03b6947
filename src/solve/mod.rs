//! Solvers of `(I − K) x = L0` (`design.md` §4): parameters in, info or a typed error out.
//!
//! Every method reports the same relative residual `‖L0 + Kx − x‖₂ / ‖L0‖₂` for every
//! iterate, the number of kernel applications and the wall time, so methods compare fairly.

mod neumann;

pub use neumann::successive_approximation;

use thiserror::Error;

/// Stopping rule shared by the iterative methods.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SolveParams {
    pub tolerance: f64,
    pub max_iterations: usize,
}

/// What a successful solve did.
#[derive(Debug, Clone, PartialEq)]
pub struct SolveInfo {
    pub method: &'static str,
    /// Iterations until the returned iterate met the tolerance.
    pub iterations: usize,
    /// Applications of the kernel `K`.
    pub applications: usize,
    /// Relative residual of iterate `n` at index `n` (the last one is the returned one's).
    pub residual_history: Vec<f64>,
    pub seconds: f64,
}

impl SolveInfo {
    pub fn residual(&self) -> f64 {
        self.residual_history.last().copied().unwrap_or(f64::NAN)
    }
}

/// Why a solve failed.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum SolveError {
    #[error("nothing emits light: the source term L0 is zero, so the solution is zero")]
    NoSource,
    #[error(
        "successive approximation diverges: the residual stopped shrinking (ratio {ratio:.9} per \
         iteration after {iterations} iterations, residual {residual:.3e}), so the spectral radius \
         of K is at least 1. A closed scene whose reflectances are all 1 has no finite solution; \
         lower a reflectance or open the scene"
    )]
    Diverges { ratio: f64, iterations: usize, residual: f64 },
    #[error(
        "no convergence after {iterations} iterations: residual {residual:.3e} (tolerance \
         {tolerance:.1e}), shrinking by {ratio:.6} per iteration; about {needed} more iterations \
         would be needed (raise max_iterations or the tolerance)"
    )]
    NoConvergence { iterations: usize, residual: f64, tolerance: f64, ratio: f64, needed: f64 },
}

pub(crate) fn norm(x: &[f64]) -> f64 {
    x.iter().map(|v| v * v).sum::<f64>().sqrt()
}
