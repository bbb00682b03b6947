//! Why an export of a kernel (`super`) was not written.

use crate::io::IoError;
use crate::kernel::TooLarge;
use thiserror::Error;

/// Why an export was not written.
#[derive(Debug, Error)]
pub enum ExportError {
    /// The files could not be written.
    #[error(transparent)]
    Io(#[from] IoError),
    /// The explicit product `B·G` would exceed the memory limit.
    #[error(transparent)]
    TooLarge(#[from] TooLarge),
    /// PETSc's binary files count in int32.
    #[error("PETSc's binary format counts in 32-bit integers: {what} is {count}, over 2147483647")]
    TooManyForPetsc {
        /// What overflows (non-zeros, rows).
        what: &'static str,
        /// Its count.
        count: usize,
    },
}
