//! A `[[grid]]`'s UGR (`docs/photometry.md`, "A grid's UGR"): the largest reading of the
//! `[[observer]]`s and of every eye position and view of the `[[glare_grid]]`s that name
//! the grid (`grid = "NAME"`), the figure checked against its `target.ugr` (EN 12464-1's
//! `UGR_L`) in the summary, the HDF5 file and the report, for the case and each light scene.

use super::glare_grid::GlareGridReading;
use super::ugr::UgrReading;

/// The UGR readings of one field (the case's or a light scene's) a grid's UGR is taken from.
#[derive(Debug, Clone, Copy)]
pub struct GlareReadings<'a> {
    /// The `[[observer]]`s' readings.
    pub observers: &'a [UgrReading],
    /// The `[[glare_grid]]`s' readings.
    pub glare_grids: &'a [GlareGridReading],
}

/// A grid's UGR and what it is taken from: how many observers and which glare grids name it.
#[derive(Debug, Clone, PartialEq)]
pub struct GridUgr {
    /// The UGR: the largest of the readings (`−∞` when none sees a luminaire).
    pub ugr: f64,
    /// The observers that name the grid.
    pub observers: usize,
    /// The glare grids that name the grid, by name.
    pub glare_grids: Vec<String>,
}

impl GlareReadings<'_> {
    /// The observers that name the grid `grid`.
    fn observers_naming<'b>(&'b self, grid: &'b str) -> impl Iterator<Item = &'b UgrReading> + 'b {
        self.observers.iter().filter(move |r| r.observer.grid.as_deref() == Some(grid))
    }

    /// The glare grids that name the grid `grid`.
    fn glare_grids_naming<'b>(&'b self, grid: &'b str) -> impl Iterator<Item = &'b GlareGridReading> + 'b {
        self.glare_grids.iter().filter(move |g| g.grid.grid.as_deref() == Some(grid))
    }

    /// The UGR of the grid named `grid` (`docs/photometry.md`, "A grid's UGR"): the largest
    /// of its observers' readings and of its glare grids' at every position and view, and
    /// what it is taken from; `None` when no observer and no glare grid names it.
    pub fn grid_ugr(&self, grid: &str) -> Option<GridUgr> {
        let glare_grids: Vec<&GlareGridReading> = self.glare_grids_naming(grid).collect();
        let observers = self.observers_naming(grid).count();
        if observers == 0 && glare_grids.is_empty() {
            return None;
        }
        let readings = self.observers_naming(grid).chain(glare_grids.iter().flat_map(|g| &g.readings));
        Some(GridUgr {
            ugr: readings.map(UgrReading::ugr).fold(f64::NEG_INFINITY, f64::max),
            observers,
            glare_grids: glare_grids.iter().map(|g| g.grid.name.clone()).collect(),
        })
    }
}
