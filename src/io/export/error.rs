//! Why an export of a kernel (`super`) was not written.

use crate::io::IoError;
use crate::kernel::TooLarge;
use thiserror::Error;

/// Why an export was not written.
#[derive(Debug, Error)]
pub enum ExportError {
    #[error(transparent)]
    Io(#[from] IoError),
    #[error(transparent)]
    TooLarge(#[from] TooLarge),
    /// PETSc's binary files count in int32.
    #[error("PETSc's binary format counts in 32-bit integers: {what} is {count}, over 2147483647")]
    TooManyForPetsc { what: &'static str, count: usize },
}
