//! The solution file as the report reads it: datasets and attributes by path, a missing
//! optional part `None` or absent, a malformed one an error naming its path.

use super::super::read::{File, Result, Why};
use hdf5::types::VarLenUnicode;

/// An open solution file.
pub(super) struct H5<'a>(pub(super) File<'a>);

impl H5<'_> {
    /// Whether the group or dataset `path` (`a/b/c`) exists, each of its parents first.
    pub(super) fn has(&self, path: &str) -> bool {
        let parts: Vec<&str> = path.split('/').collect();
        (1..=parts.len()).all(|n| self.0.h5.link_exists(&parts[..n].join("/")))
    }

    /// The numbers of the dataset `path`, flat.
    pub(super) fn numbers(&self, path: &str) -> Result<Vec<f64>> {
        self.0.raw::<f64>(path)
    }

    /// The numbers of `path`, which must hold `n`.
    pub(super) fn numbers_of(&self, path: &str, n: usize) -> Result<Vec<f64>> {
        let values = self.numbers(path)?;
        if values.len() != n {
            return Err(Why(format!("/{path} holds {} values, expected {n}", values.len())));
        }
        Ok(values)
    }

    /// The strings of the dataset `path`.
    pub(super) fn strings(&self, path: &str) -> Result<Vec<String>> {
        Ok(self.0.raw::<VarLenUnicode>(path)?.iter().map(|s| s.as_str().to_string()).collect())
    }

    /// The number attribute `name` of the group `group` (`""` for the root), if it has one.
    pub(super) fn attr(&self, group: &str, name: &str) -> Option<f64> {
        let at = if group.is_empty() { self.0.h5.attr(name) } else { self.0.h5.group(group).ok()?.attr(name) };
        at.ok()?.read_scalar::<f64>().ok()
    }

    /// The number attributes `names` of `group`, NaN where one is missing.
    pub(super) fn attrs<const N: usize>(&self, group: &str, names: [&str; N]) -> [f64; N] {
        names.map(|name| self.attr(group, name).unwrap_or(f64::NAN))
    }

    /// The text attribute `name` of the root, if it has one.
    pub(super) fn text(&self, name: &str) -> Option<String> {
        super::super::read::text(self.0.h5, name).ok()
    }
}
