//! Symmetries of photometric files: the columns a file stores, completed by their mirror
//! images into the table the lookup uses.
//!
//! A mirror plane through the polar axis at azimuth `m/2` maps the column at `a` to
//! `m − a`: `m = 0` is the C0–C180 plane (`a → −a`), `m = 180` the C90–C270 plane
//! (`a → 180° − a`); quadrant symmetry is both. Axial symmetry needs no expansion: one
//! periodic column is the same in every direction of azimuth.

use super::table::Column;

/// Azimuths closer than this (degrees) are the same column.
const SAME: f64 = 1e-6;

/// Plane C0–C180.
pub const PLANE_C0: f64 = 0.0;
/// Plane C90–C270.
pub const PLANE_C90: f64 = 180.0;

/// `columns` and their images in every plane of `mirrors`, over a full turn `[0, 360)`,
/// sorted; a stored column wins over an image at the same azimuth.
pub fn full_turn(columns: Vec<Column>, mirrors: &[f64]) -> Vec<Column> {
    expand(columns, mirrors, |a| {
        let a = a.rem_euclid(360.0);
        if a > 360.0 - SAME { 0.0 } else { a }
    })
}

/// `columns` and their images in every plane of `mirrors`, azimuths in `[−180, 180)`.
pub fn signed(columns: Vec<Column>, mirrors: &[f64]) -> Vec<Column> {
    expand(columns, mirrors, |a| (a + 180.0).rem_euclid(360.0) - 180.0)
}

fn expand(mut columns: Vec<Column>, mirrors: &[f64], normalize: impl Fn(f64) -> f64) -> Vec<Column> {
    for &m in mirrors {
        let images: Vec<Column> = columns.iter().map(|(a, c)| (m - a, c.clone())).collect();
        columns.extend(images);
    }
    for column in &mut columns {
        column.0 = normalize(column.0);
    }
    columns.sort_by(|a, b| a.0.total_cmp(&b.0));
    columns.dedup_by(|later, earlier| (later.0 - earlier.0).abs() < SAME);
    columns
}
