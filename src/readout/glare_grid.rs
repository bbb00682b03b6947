//! The UGR on a `[[glare_grid]]` (`docs/photometry.md`, "UGR on a grid of observers"): the
//! reading of CIE 117 (`ugr.rs`) at every eye position and view, the largest per position
//! and the largest of all, against the grid's `UGR_L`.

use super::field::Field;
use super::ugr::{UgrReading, read_observers};
use crate::model::Model;
use crate::scene::GlareGrid;

/// A glare grid's readings.
#[derive(Debug, Clone, PartialEq)]
pub struct GlareGridReading {
    /// The glare grid as described.
    pub grid: GlareGrid,
    /// One reading per position and view, position after position (`i·views + j`).
    pub readings: Vec<UgrReading>,
}

/// Where a glare grid's UGR is largest.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Largest {
    /// The UGR there (`−∞` when no eye sees a luminaire).
    pub ugr: f64,
    /// The position's index (`u + v·nu`).
    pub position: usize,
    /// The view's index.
    pub view: usize,
}

impl GlareGridReading {
    /// The UGR at position `position` looking along view `view` (`−∞` with no source in view).
    pub fn ugr(&self, position: usize, view: usize) -> f64 {
        self.readings[position * self.grid.views.len() + view].ugr()
    }

    /// The largest UGR over the views at each position.
    pub fn per_position(&self) -> Vec<f64> {
        let views = self.grid.views.len();
        self.readings.chunks(views).map(|r| r.iter().map(UgrReading::ugr).fold(f64::NEG_INFINITY, f64::max)).collect()
    }

    /// The largest UGR of all, and where (the first such position and view).
    pub fn largest(&self) -> Largest {
        let views = self.grid.views.len();
        let first = Largest { ugr: f64::NEG_INFINITY, position: 0, view: 0 };
        self.readings.iter().enumerate().fold(first, |best, (k, r)| match r.ugr() > best.ugr {
            true => Largest { ugr: r.ugr(), position: k / views, view: k % views },
            false => best,
        })
    }

    /// Whether the largest UGR meets `ugr_limit` (`None` without a limit).
    pub fn met(&self) -> Option<bool> {
        self.grid.ugr_limit.map(|limit| self.largest().ugr <= limit)
    }

    /// The readings whose sources include one outside the formula's solid angles.
    pub fn outside_validity(&self) -> usize {
        self.readings.iter().filter(|r| r.outside_validity() > 0).count()
    }
}

/// Reads every glare grid from a solved field.
pub fn read_glare_grids(grids: &[GlareGrid], model: &Model, field: &Field) -> Vec<GlareGridReading> {
    let read = |grid: &GlareGrid| GlareGridReading {
        grid: grid.clone(),
        readings: read_observers(&grid.observers(), model, field),
    };
    grids.iter().map(read).collect()
}
