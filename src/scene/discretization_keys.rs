//! The keys of `[discretization]` read into an [`Asked`] (`docs/design.md` §7), checked later with
//! the command line's flags by the same rules (`discretization.rs`).
//!
//! The old spelling is read with a note: `method` for `kernel` (`"explicit"` for
//! `"uniform"`), and under `method = "hierarchical"` `patch_size` for the roots, `smallest`
//! (default 0.05 m) for the finest leaves and `tolerance` for the links'.

use super::check::Context;
use super::discretization::{Asked, Given, KernelAsked, KernelKind};
use super::error::SceneError;
use super::schema::{RawDirections, RawDiscretization};
use crate::directions::Scheme;
use std::fmt;
use std::path::{Path, PathBuf};

/// A key of the old spelling, read as the new one says.
#[derive(Debug, Clone, PartialEq)]
pub struct OldSpelling {
    file: PathBuf,
    old: String,
    new: String,
}

impl fmt::Display for OldSpelling {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{}: [discretization]: {} is the old spelling of {}; read as such",
            self.file.display(),
            self.old,
            self.new
        )
    }
}

/// `[discretization]` as asked for, with a note for each key of the old spelling.
pub(super) fn asked(path: &Path, raw: Option<RawDiscretization>) -> Result<(Asked, Vec<OldSpelling>), SceneError> {
    let at = Context::new(path, "[discretization]");
    let raw = raw.ok_or_else(|| at.error("", "the table [discretization] is required"))?;
    let patch_size = Some(Given::key("patch_size")(raw.patch_size));
    let mut asked = Asked { patch_size, directions: Some(directions(&at, &raw)?), ..Asked::default() };
    let kernel = match (&raw.kernel, &raw.method) {
        (Some(_), Some(_)) => return Err(at.error("method", "is the old spelling of `kernel`: give `kernel` only")),
        (Some(name), None) => name.as_str(),
        (None, Some(name)) => name.as_str(),
        (None, None) => "auto",
    };
    let named_by = if raw.method.is_some() { "method" } else { "kernel" };
    let kind = KernelAsked::parse(kernel)
        .ok_or_else(|| at.error(named_by, format!("unknown kernel \"{kernel}\"; give {}", KernelKind::NAMES)))?;
    asked.kernel = Some(Given::key(named_by)(kind));
    if raw.method.is_none() {
        let old = "is the old spelling (with `method`); with `kernel`, give";
        if raw.tolerance.is_some() {
            return Err(at.error("tolerance", format!("{old} link_tolerance")));
        }
        if raw.smallest.is_some() {
            return Err(at.error("smallest", format!("{old} patch_size, the finest leaves (root_size the roots)")));
        }
        asked.root_size = raw.root_size.map(Given::key("root_size"));
        asked.link_tolerance = raw.link_tolerance.map(Given::key("link_tolerance"));
        return Ok((asked, Vec::new()));
    }
    old_spelling(&at, &raw, kind, asked)
}

/// `method` and, for `"hierarchical"`, its `patch_size`, `smallest` and `tolerance`.
fn old_spelling(
    at: &Context,
    raw: &RawDiscretization,
    kind: KernelAsked,
    mut asked: Asked,
) -> Result<(Asked, Vec<OldSpelling>), SceneError> {
    for (key, value) in [("root_size", raw.root_size), ("link_tolerance", raw.link_tolerance)] {
        if value.is_some() {
            return Err(at.error(key, "is the new spelling: give `kernel` instead of `method` with it"));
        }
    }
    let note = |old: String, new: String| OldSpelling { file: at.file.to_path_buf(), old, new };
    let method = raw.method.as_deref().unwrap_or_default();
    let mut notes = vec![note(format!("`method = \"{method}\"`"), format!("`kernel = \"{}\"`", kind.name()))];
    if kind != KernelAsked::Hierarchical {
        for (key, value) in [("tolerance", raw.tolerance), ("smallest", raw.smallest)] {
            if value.is_some() {
                return Err(at.error(key, "applies only to method = \"hierarchical\""));
            }
        }
        return Ok((asked, notes));
    }
    // without `smallest`, the hierarchy's own default leaves (0.05 m)
    let smallest = raw.smallest.unwrap_or(crate::kernel::hierarchy::Options::default().patch_size);
    if smallest > raw.patch_size && smallest.is_finite() && raw.patch_size > 0.0 {
        let message =
            format!("the smallest element ({smallest} m) exceeds patch_size ({} m), the roots", raw.patch_size);
        return Err(at.error("smallest", message));
    }
    asked.root_size = Some(Given::key("patch_size")(raw.patch_size));
    asked.patch_size = Some(Given::key(if raw.smallest.is_some() { "smallest" } else { "patch_size" })(smallest));
    asked.link_tolerance = raw.tolerance.map(Given::key("tolerance"));
    let roots = format!("`patch_size = {}`", raw.patch_size);
    notes.push(note(roots, format!("`root_size = {}` (patch_size is now the finest leaves)", raw.patch_size)));
    notes.push(note(format!("`smallest = {smallest}`"), format!("`patch_size = {smallest}`")));
    if let Some(t) = raw.tolerance {
        notes.push(note(format!("`tolerance = {t}`"), format!("`link_tolerance = {t}`")));
    }
    Ok((asked, notes))
}

/// `directions`: a cell count or a scheme's name (default one cell).
fn directions(at: &Context, raw: &RawDiscretization) -> Result<Scheme, SceneError> {
    let name = match &raw.directions {
        None => "1".to_string(),
        Some(RawDirections::Count(k)) => k.to_string(),
        Some(RawDirections::Name(name)) => name.clone(),
    };
    Scheme::parse(&name).ok_or_else(|| match name.parse::<u128>() {
        Ok(k) if k > Scheme::MAX_CELLS as u128 => at.error(
            "directions",
            format!("out of range: at most {} cells (cell indices are 16-bit), got {k}", Scheme::MAX_CELLS),
        ),
        _ => at.error("directions", format!("unknown direction set \"{name}\"; give {}", Scheme::NAMES)),
    })
}
