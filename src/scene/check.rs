//! What every table's validation shares: where a value sits (file, table, key) and the
//! rules of numbers, points and directions, names, and the geometric tolerance.

use super::error::SceneError;
use glam::DVec3;
use serde_spanned::Spanned;
use std::path::Path;

/// Relative tolerance (to the shape's size) of the planarity, collinearity,
/// coincidence and parallel-edge tests.
pub(super) const REL_TOL: f64 = 1e-6;

/// An area below this fraction of (size)² counts as zero.
pub(super) const ZERO_AREA: f64 = 1e-12;

/// The largest luminance (cd/m²), flux (lm), intensity (cd), illuminance (lx) or
/// multiplier a case may give: 10¹¹ times the sun's luminance, far below the range of
/// doubles, so that no sum over patches and cells overflows.
pub(super) const MAGNITUDE: f64 = 1e20;

/// The largest coordinate or length of the scene's geometry, m (1,000 km): rays are cast in
/// single precision, which at this distance from the origin tells points apart only to
/// 6 cm, and every area and patch count stays far inside the range of doubles.
pub(super) const COORDINATE: f64 = 1e6;

pub(super) struct Context<'a> {
    pub(super) file: &'a Path,
    table: String,
}

impl<'a> Context<'a> {
    pub(super) fn new(file: &'a Path, table: impl Into<String>) -> Self {
        Context { file, table: table.into() }
    }

    /// The context of the `index`-th (0-based) `[[kind]]` table, named `name`.
    pub(super) fn item(file: &'a Path, kind: &str, name: &str, index: usize) -> Self {
        Context::new(file, format!("[[{kind}]] \"{name}\" (#{})", index + 1))
    }

    pub(super) fn error(&self, key: &str, message: impl Into<String>) -> SceneError {
        SceneError::new(self.file, self.table.clone(), key, message)
    }

    pub(super) fn finite(&self, key: &str, x: f64) -> Result<f64, SceneError> {
        match x.is_finite() {
            true => Ok(x),
            false => Err(self.error(key, format!("must be a finite number, got {}", number(x)))),
        }
    }

    pub(super) fn positive(&self, key: &str, x: f64) -> Result<f64, SceneError> {
        match self.finite(key, x)? > 0.0 {
            true => Ok(x),
            false => Err(self.error(key, format!("must be greater than 0, got {}", number(x)))),
        }
    }

    pub(super) fn non_negative(&self, key: &str, x: f64) -> Result<f64, SceneError> {
        match self.finite(key, x)? >= 0.0 {
            true => Ok(x),
            false => Err(self.error(key, format!("must be at least 0, got {}", number(x)))),
        }
    }

    /// A photometric magnitude (luminance, flux, intensity, illuminance, multiplier) in
    /// `(0, MAGNITUDE]`: larger values are no light on Earth and overflow the sums of the
    /// field before they reach a solver.
    pub(super) fn magnitude(&self, key: &str, x: f64, unit: &str) -> Result<f64, SceneError> {
        match self.finite(key, x)? <= MAGNITUDE {
            true => Ok(x),
            false => Err(self.error(key, format!("out of range: at most {MAGNITUDE:e}{unit}, got {x:e}"))),
        }
    }

    pub(super) fn point(&self, key: &str, v: [f64; 3]) -> Result<DVec3, SceneError> {
        let p = DVec3::from_array(v);
        match p.is_finite() {
            true => Ok(p),
            false => Err(self.error(key, format!("must have finite coordinates, got {}", show(p)))),
        }
    }

    /// A point (or an edge, a translation) of the geometry, finite and within
    /// `±COORDINATE` m on every axis.
    pub(super) fn place(&self, key: &str, v: [f64; 3]) -> Result<DVec3, SceneError> {
        let p = self.point(key, v)?;
        match p.abs().max_element() <= COORDINATE {
            true => Ok(p),
            false => Err(self.error(key, out_of_range(format!("[{:e}, {:e}, {:e}]", p.x, p.y, p.z)))),
        }
    }

    /// A length of the geometry (a radius), m, in `(0, COORDINATE]`.
    pub(super) fn length(&self, key: &str, x: f64) -> Result<f64, SceneError> {
        match self.positive(key, x)? <= COORDINATE {
            true => Ok(x),
            false => Err(self.error(key, out_of_range(format!("{x:e} m")))),
        }
    }

    /// A non-zero vector, normalized.
    pub(super) fn direction(&self, key: &str, v: [f64; 3]) -> Result<DVec3, SceneError> {
        let d = self.point(key, v)?;
        d.try_normalize().ok_or_else(|| self.error(key, format!("must be a non-zero vector, got {}", show(d))))
    }
}

/// The refusal of a coordinate or length beyond `COORDINATE`.
pub(super) fn out_of_range(got: String) -> String {
    format!(
        "out of range: coordinates and lengths are at most {COORDINATE:e} m (1,000 km; rays are cast in single \
         precision), got {got}"
    )
}

/// `[x, y, z]` as written in TOML (each coordinate as [`number`]).
pub(super) fn show(v: DVec3) -> String {
    format!("[{}, {}, {}]", number(v.x), number(v.y), number(v.z))
}

/// A number as a message quotes it: as written between 1e-4 and 1e7 in size (and 0),
/// else in exponent form (`1e308`, not 309 digits).
pub fn number(x: f64) -> String {
    if x == 0.0 || !x.is_finite() || (1e-4..1e7).contains(&x.abs()) { format!("{x}") } else { format!("{x:e}") }
}

/// Names must be non-empty and unique among the `[[kind]]` tables.
pub(super) fn unique_names<'n>(
    path: &Path,
    kind: &str,
    names: impl Iterator<Item = &'n str>,
) -> Result<(), SceneError> {
    let mut seen: Vec<&str> = Vec::new();
    for (index, name) in names.enumerate() {
        let at = Context::item(path, kind, name, index);
        if name.is_empty() {
            return Err(at.error("name", "must not be empty"));
        }
        if let Some(first) = seen.iter().position(|&s| s == name) {
            let message = format!("duplicate name \"{name}\" (also [[{kind}]] #{})", first + 1);
            return Err(at.error("name", message));
        }
        seen.push(name);
    }
    Ok(())
}

/// `line N: ` of the value at `span` in `source`.
pub(super) fn line<T>(source: &str, value: &Spanned<T>) -> String {
    let at = value.span().start.min(source.len());
    format!("line {}: ", source.as_bytes()[..at].iter().filter(|&&b| b == b'\n').count() + 1)
}
