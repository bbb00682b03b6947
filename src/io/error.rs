//! Why a file could not be written or read back: the path and what went wrong there.

use crate::interrupt::Interrupted;
use std::fmt::Display;
use std::path::{Path, PathBuf};
use thiserror::Error;

#[derive(Debug, Error)]
pub enum IoError {
    #[error("cannot write {}: {why}", path.display())]
    Write { path: PathBuf, why: String },
    #[error("cannot open {} as HDF5: {why}", path.display())]
    Open { path: PathBuf, why: String },
    #[error("cannot read {}: {why}", path.display())]
    Read { path: PathBuf, why: String },
    /// A file that opened but does not hold what ugo writes.
    #[error("{} is not a ugo solution file: {why}", path.display())]
    NotASolution { path: PathBuf, why: String },
    /// A file without a usable `/kernel` group (`ugo solve --save-kernel` writes one).
    #[error("{} holds no usable kernel: {why}", path.display())]
    NotAKernel { path: PathBuf, why: String },
    /// A file without the asked-for eigenvector in `/spectrum` (`ugo norms --spectrum N`).
    #[error("{} holds no such mode: {why}", path.display())]
    NoMode { path: PathBuf, why: String },
    /// A light scene the solution does not hold (`known`: the ones it holds, listed).
    #[error("{} has no light scene \"{name}\"; its light scenes: {known}", path.display())]
    NoLightScene { path: PathBuf, name: String, known: String },
    /// A signal asked the process to stop before the file was complete.
    #[error("{} not written ({stop}); a previous file of that name is left as it was", path.display())]
    Interrupted { path: PathBuf, stop: Interrupted },
}

impl IoError {
    pub fn write(path: &Path, why: impl Display) -> IoError {
        IoError::Write { path: path.to_path_buf(), why: why.to_string() }
    }

    pub fn read(path: &Path, why: impl Display) -> IoError {
        IoError::Read { path: path.to_path_buf(), why: why.to_string() }
    }
}
