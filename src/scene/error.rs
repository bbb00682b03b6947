//! [`SceneError`]: what is wrong with a case file, and where (file, table, key).

use std::fmt;
use std::path::{Path, PathBuf};

/// A case file that cannot be read, parsed or validated.
///
/// Displays as ``cases/x.toml: [[surface]] "floor" (#3), key `reflectance`: must be at most 1, got 1.2``;
/// the table and key parts are left out when empty.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub struct SceneError {
    file: PathBuf,
    table: String,
    key: String,
    message: String,
}

impl SceneError {
    /// An error in `file`, inside `table` (e.g. `[[surface]] "floor" (#3)`), about `key`.
    pub fn new(file: &Path, table: impl Into<String>, key: impl Into<String>, message: impl Into<String>) -> Self {
        SceneError { file: file.to_path_buf(), table: table.into(), key: key.into(), message: message.into() }
    }

    /// The case file.
    pub fn file(&self) -> &Path {
        &self.file
    }

    /// The table the error is in, e.g. `[[surface]] "floor" (#3)`; empty for the whole file.
    pub fn table(&self) -> &str {
        &self.table
    }

    /// The offending key (dotted for inline tables, e.g. `emission.flux`); empty if none.
    pub fn key(&self) -> &str {
        &self.key
    }

    /// What is wrong.
    pub fn message(&self) -> &str {
        &self.message
    }
}

impl fmt::Display for SceneError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}:", self.file.display())?;
        match (self.table.is_empty(), self.key.is_empty()) {
            (true, true) => {}
            (false, true) => write!(f, " {}:", self.table)?,
            (true, false) => write!(f, " key `{}`:", self.key)?,
            (false, false) => write!(f, " {}, key `{}`:", self.table, self.key)?,
        }
        write!(f, " {}", self.message)
    }
}
