//! The one shape of every solver (`docs/design.md` §4): the stopping rule in, what the solve
//! did or why it failed out, and the vector helpers the methods share.

use super::range::OutOfRange;
use crate::interrupt::Interrupted;
use thiserror::Error;

/// What every method takes: the stopping rule of the iterative ones, GMRES's restart
/// length, and the memory the direct ones may use for their factors.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SolveParams {
    /// Relative residual `‖L0 + Kx − x‖₂/‖L0‖₂` at which an iteration stops.
    pub tolerance: f64,
    /// Kernel applications after which an iteration gives up.
    pub max_iterations: usize,
    /// GMRES restart length `m`.
    pub restart: usize,
    /// Largest memory of LU factors, bytes.
    pub memory_limit: u64,
}

impl Default for SolveParams {
    /// Tolerance 1e-8, 10,000 iterations, GMRES(30), half the machine's memory.
    fn default() -> Self {
        SolveParams {
            tolerance: 1e-8,
            max_iterations: 10_000,
            restart: 30,
            memory_limit: crate::kernel::memory::default_limit(),
        }
    }
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
    /// Kernel applications spent when each residual was recorded.
    pub application_history: Vec<usize>,
    /// Seconds since the start when each residual was recorded.
    pub time_history: Vec<f64>,
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
    #[error(
        "{method} stagnated: the residual stayed at {residual:.3e} over the last restart cycle \
         ({iterations} iterations); raise the restart length or use the direct solver"
    )]
    Stagnation { method: &'static str, iterations: usize, residual: f64 },
    #[error("{method} broke down after {iterations} iterations ({why}); use GMRES or the direct solver")]
    Breakdown { method: &'static str, iterations: usize, why: &'static str },
    #[error("{0}")]
    TooLarge(String),
    #[error(
        "{method} returned a solution {growth:.1e} times larger than the emission: I − K is singular \
         or nearly so (spectral radius ≥ 1, e.g. a closed scene whose reflectances are all 1)"
    )]
    Singular { method: &'static str, growth: f64 },
    #[error("{method} needs {needs}")]
    Unsupported { method: &'static str, needs: &'static str },
    /// An overflow or NaN in the iterate, or a source term whose norm overflows.
    #[error("{0}")]
    OutOfRange(Box<OutOfRange>),
    /// A signal asked the process to stop.
    #[error(transparent)]
    Interrupted(#[from] Interrupted),
}

pub(crate) fn norm(x: &[f64]) -> f64 {
    dot(x, x).sqrt()
}

pub(crate) fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}
