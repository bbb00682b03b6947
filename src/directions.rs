//! Direction sets `{C_k}`: partitions of the hemisphere of outgoing directions (`design.md` §2).
//!
//! Each cell has a representative direction in the patch's local frame `(t, b, N)`, its
//! solid angle `ω_k` and projected solid angle `μ_k = ∫_{C_k} cosθ dω` (`Σ μ_k = π`). The
//! one-cell set is classic radiosity; finer partitions plug in here without changing the
//! kernel's shape (unknowns `x[i·K + k]`).

use glam::DVec3;
use std::f64::consts::PI;

/// One direction cell.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cell {
    /// Representative unit direction, local frame (z along the normal).
    pub direction: DVec3,
    /// Solid angle, sr.
    pub solid_angle: f64,
    /// Projected solid angle `∫ cosθ dω`, sr.
    pub projected: f64,
}

/// A partition of the hemisphere into `K` cells.
#[derive(Debug, Clone, PartialEq)]
pub struct DirectionSet {
    cells: Vec<Cell>,
}

impl DirectionSet {
    /// `K = 1`: the whole hemisphere, radiosity.
    pub fn single() -> DirectionSet {
        DirectionSet { cells: vec![Cell { direction: DVec3::Z, solid_angle: 2.0 * PI, projected: PI }] }
    }

    pub fn len(&self) -> usize {
        self.cells.len()
    }

    pub fn is_empty(&self) -> bool {
        self.cells.is_empty()
    }

    pub fn cells(&self) -> &[Cell] {
        &self.cells
    }

    /// The cell holding a local-frame direction of the upper hemisphere (the one-cell
    /// set holds them all).
    pub fn lookup(&self, _local: DVec3) -> usize {
        0
    }
}
