//! The one shape of every solver (`docs/design.md` §4): the stopping rule in, what the solve
//! did or why it failed out, and the vector helpers the methods share.

use super::algorithm::Algorithm;
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
    /// The algorithm that ran.
    pub method: Algorithm,
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
    /// Wall time of the solve, s.
    pub seconds: f64,
}

impl SolveInfo {
    /// The relative residual of the returned iterate (NaN if none was recorded).
    pub fn residual(&self) -> f64 {
        self.residual_history.last().copied().unwrap_or(f64::NAN)
    }
}

/// Why a solve failed.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum SolveError {
    /// The source term is zero: nothing to solve.
    #[error("nothing emits light: the source term L0 is zero, so the solution is zero")]
    NoSource,
    /// Successive approximation stopped converging: `ρ(K) ≥ 1`.
    #[error(
        "successive approximation diverges: the residual stopped shrinking (ratio {ratio:.9} per \
         iteration after {iterations} iterations, residual {residual:.3e}), so the spectral radius \
         of K is at least 1. A closed scene whose reflectances are all 1 has no finite solution; \
         lower a reflectance or open the scene"
    )]
    Diverges {
        /// Mean residual ratio per iteration.
        ratio: f64,
        /// Iterations done.
        iterations: usize,
        /// The last relative residual.
        residual: f64,
    },
    /// The iteration limit was reached before the tolerance.
    #[error(
        "no convergence after {iterations} iterations: residual {residual:.3e} (tolerance \
         {tolerance:.1e}), shrinking by {ratio:.6} per iteration; about {needed} more iterations \
         would be needed (raise max_iterations or the tolerance)"
    )]
    NoConvergence {
        /// Iterations done.
        iterations: usize,
        /// The last relative residual.
        residual: f64,
        /// The tolerance asked for.
        tolerance: f64,
        /// Mean residual ratio per iteration.
        ratio: f64,
        /// Iterations still needed at that ratio.
        needed: f64,
    },
    /// GMRES gained less than 0.1 % over a restart cycle.
    #[error(
        "{method} stagnated: the residual stayed at {residual:.3e} over the last restart cycle \
         ({iterations} iterations); raise the restart length or use the direct solver"
    )]
    Stagnation {
        /// The method's name.
        method: &'static str,
        /// Iterations done.
        iterations: usize,
        /// The relative residual it stayed at.
        residual: f64,
    },
    /// A method broke down: BiCGSTAB's recurrence (a vanishing denominator) or a sparse LU.
    #[error("{method} broke down after {iterations} iterations ({why}); use GMRES or the direct solver")]
    Breakdown {
        /// The method's name.
        method: &'static str,
        /// Iterations done.
        iterations: usize,
        /// What failed.
        why: &'static str,
    },
    /// A direct solver's factors would exceed the memory limit, or its matrix could not be built.
    #[error("{0}")]
    TooLarge(String),
    /// The solution is over `1e10` times the emission (or the LU met a zero pivot): `I − K`
    /// is singular.
    #[error(
        "{method} returned a solution {growth:.1e} times larger than the emission: I − K is singular \
         or nearly so (spectral radius ≥ 1, e.g. a closed scene whose reflectances are all 1)"
    )]
    Singular {
        /// The algorithm that ran.
        method: Algorithm,
        /// `‖x‖/‖L0‖` (infinite for a zero pivot).
        growth: f64,
    },
    /// The method cannot run on this system.
    #[error("{method} needs {needs}")]
    Unsupported {
        /// The method's name.
        method: &'static str,
        /// What it needs.
        needs: &'static str,
    },
    /// An overflow or NaN in the iterate, or a source term whose norm overflows.
    #[error("{0}")]
    OutOfRange(Box<OutOfRange>),
    /// A signal asked the process to stop.
    #[error(transparent)]
    Interrupted(#[from] Interrupted),
    /// The system gave no thread for a direct factorization.
    #[error("the system gave no thread for {what}: {why}")]
    NoThread {
        /// The factorization's name.
        what: &'static str,
        /// The system's reason.
        why: String,
    },
}

pub(crate) fn norm(x: &[f64]) -> f64 {
    dot(x, x).sqrt()
}

pub(crate) fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}
