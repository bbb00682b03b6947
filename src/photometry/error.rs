//! [`PhotometryError`]: what is wrong with a photometric file, and where (file, line).

use std::fmt;
use std::path::{Path, PathBuf};

/// A photometric file that cannot be read or does not follow its format.
///
/// Displays as `lamps/down.ies: line 14: expected 19 vertical angles, found 7 before the
/// end of the file`; the line is left out when the error concerns the whole file.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub struct PhotometryError {
    file: PathBuf,
    line: Option<usize>,
    message: String,
}

impl PhotometryError {
    /// An error at `line` (1-based) of `file`.
    pub fn at(file: &Path, line: usize, message: impl Into<String>) -> Self {
        PhotometryError { file: file.to_path_buf(), line: Some(line), message: message.into() }
    }

    /// An error about the whole of `file` (it cannot be read, say).
    pub fn whole(file: &Path, message: impl Into<String>) -> Self {
        PhotometryError { file: file.to_path_buf(), line: None, message: message.into() }
    }

    /// The 1-based line the error is on, when it is on one.
    pub fn line(&self) -> Option<usize> {
        self.line
    }
}

impl fmt::Display for PhotometryError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}:", self.file.display())?;
        if let Some(line) = self.line {
            write!(f, " line {line}:")?;
        }
        write!(f, " {}", self.message)
    }
}
