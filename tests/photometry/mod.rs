//! Tests of the photometric distributions and file readers (`ugo::photometry`): synthetic
//! IES and EULUMDAT files of every symmetry against their closed-form flux, the angle
//! systems, and malformed files refused with a line number.

mod files;
mod malformed;
mod systems;

use std::path::{Path, PathBuf};
use ugo::photometry::{IntensityDistribution, read_ies, read_ldt};

/// A synthetic file of `tests/data/photometry/`.
fn data(name: &str) -> PathBuf {
    Path::new("tests/data/photometry").join(name)
}

/// Reads a synthetic file by its extension.
fn read(name: &str) -> IntensityDistribution {
    let path = data(name);
    let read = if name.ends_with(".ldt") { read_ldt(&path) } else { read_ies(&path) };
    read.unwrap_or_else(|e| panic!("{e}"))
}
