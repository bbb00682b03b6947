//! The luminance field `L(r_i, l_k)`: an `N × K × C` array over patches, direction
//! cells and colour channels (`docs/design.md` §2; photometric `C = 1`).
//!
//! Unknowns are point-major, `x[i·K + k]`; this module owns the conversion between the
//! solver's flat vector and the array.

use ndarray::Array3;

/// Luminance of every patch in every direction cell, cd/m².
#[derive(Debug, Clone, PartialEq)]
pub struct Field {
    /// `N × K × C` (patch, cell, channel; `C = 1`), cd/m².
    pub luminance: Array3<f64>,
}

impl Field {
    /// The field of a flat unknown vector with `cells` direction cells per patch.
    pub fn from_unknowns(x: &[f64], cells: usize) -> Field {
        let n = x.len() / cells;
        let luminance = Array3::from_shape_vec((n, cells, 1), x.to_vec()).expect("x has N·K entries");
        Field { luminance }
    }

    /// Number of patches, `N`.
    pub fn patches(&self) -> usize {
        self.luminance.shape()[0]
    }

    /// Direction cells per patch, `K`.
    pub fn cells(&self) -> usize {
        self.luminance.shape()[1]
    }

    /// `L(i, k)` for the photometric channel.
    pub fn at(&self, patch: usize, cell: usize) -> f64 {
        self.luminance[[patch, cell, 0]]
    }

    /// `max_k |L(i, k)|`: a bound on what patch `i` sends in any direction.
    pub fn brightest(&self, patch: usize) -> f64 {
        (0..self.cells()).map(|k| self.at(patch, k).abs()).fold(0.0, f64::max)
    }
}
