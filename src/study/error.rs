//! [`StudyError`]: why a study gave no field (`docs/design.md` §6).

use super::kernel::KernelError;
use crate::basis::BasisError;
use crate::interrupt::Interrupted;
use crate::kernel::TooLarge;
use crate::model::ModelError;
use crate::solve::{ArnoldiError, Method, SolveError};
use thiserror::Error;

/// Why a solve gave no field.
#[derive(Debug, Error)]
pub enum StudyError {
    /// The explicit product or a direct solver's factors would exceed the memory limit.
    #[error(transparent)]
    TooLarge(#[from] TooLarge),
    /// The model could not be built.
    #[error(transparent)]
    Model(#[from] ModelError),
    /// The kernel file could not be reused.
    #[error(transparent)]
    Kernel(#[from] KernelError),
    /// The angular basis does not fit the direction set.
    #[error(transparent)]
    Basis(#[from] BasisError),
    /// A solve failed.
    #[error(transparent)]
    Solve(#[from] SolveError),
    /// The spectrum could not be computed.
    #[error(transparent)]
    Spectrum(#[from] ArnoldiError),
    /// Every method asked for failed; each with its error.
    #[error("every method failed: {}", .0.iter().map(|(m, e)| format!("{}: {e}", m.name())).collect::<Vec<_>>().join("; "))]
    EveryMethodFailed(Vec<(Method, SolveError)>),
    /// A signal stopped a stage whose loops return no `Result` (the readouts, the forward
    /// reference): `crate::interrupt`.
    #[error(transparent)]
    Interrupted(#[from] Interrupted),
    /// `ugo readout`: the stored field is not the case's.
    #[error(transparent)]
    Readout(#[from] super::readout_error::ReadoutError),
    /// A solution file could not be read.
    #[error(transparent)]
    Io(#[from] crate::io::IoError),
    /// `--strict`: warnings found before the solve (the model alone shows them).
    #[error("--strict: {} warning(s) found before the solve, nothing solved or written: {}", .0.len(), .0.iter().map(|w| crate::io::one_line(&w.to_string())).collect::<Vec<_>>().join("; "))]
    Strict(Vec<crate::io::Warning>),
}

impl StudyError {
    /// Whether the model or one of its matrices was refused as too large for the memory
    /// limit (`kernel::TooLarge`, however deep).
    pub fn too_large(&self) -> bool {
        let model = |e: &ModelError| matches!(e, ModelError::TooLarge(_));
        match self {
            StudyError::TooLarge(_) => true,
            StudyError::Model(e) | StudyError::Kernel(KernelError::Model(e)) => model(e),
            _ => false,
        }
    }
}
