//! Why a file could not be written or read back: the path and what went wrong there.

use crate::interrupt::Interrupted;
use std::fmt::Display;
use std::path::{Path, PathBuf};
use thiserror::Error;

/// Why a file could not be written or read; every variant names the file.
#[derive(Debug, Error)]
pub enum IoError {
    /// A file that could not be written, and why.
    #[error("cannot write {}: {why}", path.display())]
    Write {
        /// The file.
        path: PathBuf,
        /// What went wrong.
        why: String,
    },
    /// A file that could not be opened as HDF5, and why.
    #[error("cannot open {} as HDF5: {why}", path.display())]
    Open {
        /// The file.
        path: PathBuf,
        /// What went wrong.
        why: String,
    },
    /// A file that could not be read, and why.
    #[error("cannot read {}: {why}", path.display())]
    Read {
        /// The file.
        path: PathBuf,
        /// What went wrong.
        why: String,
    },
    /// A file that opened but does not hold what ugo writes.
    #[error("{} is not a ugo solution file: {why}", path.display())]
    NotASolution {
        /// The file.
        path: PathBuf,
        /// What it lacks.
        why: String,
    },
    /// An HDF5 file without `/field`: not a solution, or one of an older layout.
    #[error("{} has no /field: not a ugo solution, or written by an older version", path.display())]
    NoField {
        /// The file.
        path: PathBuf,
    },
    /// A file without a usable `/kernel` group (`ugo solve --save-kernel` writes one).
    #[error("{} holds no usable kernel: {why}", path.display())]
    NotAKernel {
        /// The file.
        path: PathBuf,
        /// What it lacks.
        why: String,
    },
    /// A file without the asked-for eigenvector in `/spectrum` (`ugo norms --spectrum N`).
    #[error("{} holds no such mode: {why}", path.display())]
    NoMode {
        /// The file.
        path: PathBuf,
        /// What it lacks.
        why: String,
    },
    /// A light scene the solution does not hold (`known`: the ones it holds, listed).
    #[error("{} has no light scene \"{name}\"; its light scenes: {known}", path.display())]
    NoLightScene {
        /// The solution file.
        path: PathBuf,
        /// The light scene asked for.
        name: String,
        /// The light scenes it holds, listed.
        known: String,
    },
    /// Another running process writes the same output (`io::lock`).
    #[error(
        "another ugo is writing {} (it holds {}): wait for it to end or give another output path",
        path.display(),
        lock.display()
    )]
    Busy {
        /// The output path.
        path: PathBuf,
        /// Its lock file.
        lock: PathBuf,
    },
    /// A signal asked the process to stop before the file was complete.
    #[error("{} not written ({stop}); a previous file of that name is left as it was", path.display())]
    Interrupted {
        /// The file not written.
        path: PathBuf,
        /// The signal's stop.
        stop: Interrupted,
    },
}

impl IoError {
    /// [`IoError::Write`] of `path` for the reason `why`.
    pub fn write(path: &Path, why: impl Display) -> IoError {
        IoError::Write { path: path.to_path_buf(), why: why.to_string() }
    }

    /// [`IoError::Read`] of `path` for the reason `why`.
    pub fn read(path: &Path, why: impl Display) -> IoError {
        IoError::Read { path: path.to_path_buf(), why: why.to_string() }
    }
}
