//! Illuminance calculation grids (`[[grid]]`): the illuminance `E = π Σ_d I_d` (lx) at
//! the centre of every grid cell, gathered from the solved field exactly as a probe's
//! (`probe.rs`, `docs/design.md` §5), and the statistics lighting designers judge a
//! lighting scheme by: average, minimum, maximum and the uniformity `U0 = E_min/E_avg`,
//! over the points that stand in the room (`obstructed.rs` finds the others).

use crate::model::Model;
use crate::progress::Progress;
use crate::readout::field::Field;
use crate::readout::gather::illuminance_and_direct_each;
use crate::readout::lit::Lit;
use crate::readout::obstructed::{Obstruction, obstructions};
use crate::scene::Grid;
use glam::DVec3;

/// One grid's calculation points and their illuminance, row by row along `edge_u`.
#[derive(Debug, Clone, PartialEq)]
pub struct GridReading {
    /// The grid as the case file defines it.
    pub grid: Grid,
    /// The calculation points, at the centres of the cells, m.
    pub points: Vec<DVec3>,
    /// lx, one value per point.
    pub illuminance: Vec<f64>,
    /// The part of `illuminance` directly from the sources, lx.
    pub direct: Vec<f64>,
    /// Per point, what makes it left out of the statistics (inside a solid, under a
    /// surface nearer than the spacing), or `None` for a point that counts.
    pub obstructed: Vec<Option<Obstruction>>,
}

/// Summary of a grid's illuminance, lx (and `u0`, dimensionless).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GridStats {
    /// Average illuminance `E_avg`, lx.
    pub average: f64,
    /// Smallest illuminance `E_min`, lx.
    pub min: f64,
    /// Largest illuminance `E_max`, lx.
    pub max: f64,
    /// Uniformity `E_min / E_avg` (0 when the average is 0).
    pub u0: f64,
    /// Points counted (not obstructed); every statistic is NaN when none is.
    pub counted: usize,
}

impl GridReading {
    /// The illuminance at every calculation point of `grid`, each point told to `progress`;
    /// a signal's stop leaves the points after it unread (`crate::interrupt`: the caller checks).
    pub fn of(grid: &Grid, model: &Model, field: &Field, progress: &dyn Progress) -> GridReading {
        GridReading::cut_by(grid, model, field, &[], progress)
    }

    /// [`GridReading::of`], each point's gather cut along shadow edges by the rules of the
    /// fields `by` (`cut.rs`: fields whose readings are summed; none: the field's own).
    pub fn cut_by(grid: &Grid, model: &Model, field: &Field, by: &[&Field], progress: &dyn Progress) -> GridReading {
        GridReading::each(grid, model, &[Lit::own(model, field)], by, progress).swap_remove(0)
    }

    /// [`GridReading::cut_by`] for each field of `lits` under its own light, every point's
    /// gather shared among them (`lit.rs`).
    pub fn each(grid: &Grid, model: &Model, lits: &[Lit], by: &[&Field], progress: &dyn Progress) -> Vec<GridReading> {
        let mut read: Vec<(Vec<f64>, Vec<f64>)> = vec![(Vec::new(), Vec::new()); lits.len()];
        for &p in grid.points().iter().take_while(|_| !crate::interrupt::asked()) {
            let each = illuminance_and_direct_each(model, lits, p, grid.normal, by);
            for ((illuminance, direct), (e, d)) in read.iter_mut().zip(each) {
                illuminance.push(e);
                direct.push(d);
            }
            progress.advance(1);
        }
        read.into_iter().map(|(illuminance, direct)| GridReading::with(grid, model, illuminance, direct)).collect()
    }

    /// The reading of `grid` whose points read `illuminance`, of it `direct` (lx): its
    /// points and which of them `model` obstructs.
    pub fn with(grid: &Grid, model: &Model, illuminance: Vec<f64>, direct: Vec<f64>) -> GridReading {
        let points = grid.points();
        let obstructed = obstructions(model, grid, &points);
        GridReading { grid: grid.clone(), points, illuminance, direct, obstructed }
    }

    /// `Σ w·R` over the `(w, R)` of `parts` (readings of one grid, each of one group's
    /// field read by [`GridReading::cut_by`] the groups' rules): the reading of `Σ w x`.
    pub fn superpose(parts: &[(f64, &GridReading)]) -> Option<GridReading> {
        let (_, first) = parts.first()?;
        let mut sum = GridReading {
            illuminance: vec![0.0; first.points.len()],
            direct: vec![0.0; first.points.len()],
            ..(*first).clone()
        };
        for (w, part) in parts {
            sum.illuminance.iter_mut().zip(&part.illuminance).for_each(|(s, e)| *s += w * e);
            sum.direct.iter_mut().zip(&part.direct).for_each(|(s, e)| *s += w * e);
        }
        Some(sum)
    }

    /// The statistics of the illuminance over the points that count.
    pub fn stats(&self) -> GridStats {
        self.stats_of(&self.illuminance)
    }

    /// The statistics of `values` (one per point, as the illuminance) over the points that
    /// count; every point has the same weight: the cells are equal.
    pub fn stats_of(&self, values: &[f64]) -> GridStats {
        let e: Vec<f64> = values.iter().zip(&self.obstructed).filter(|(_, o)| o.is_none()).map(|(e, _)| *e).collect();
        if e.is_empty() {
            return GridStats { average: f64::NAN, min: f64::NAN, max: f64::NAN, u0: f64::NAN, counted: 0 };
        }
        let average = e.iter().sum::<f64>() / e.len() as f64;
        let min = e.iter().copied().fold(f64::INFINITY, f64::min);
        let max = e.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        GridStats { average, min, max, u0: if average > 0.0 { min / average } else { 0.0 }, counted: e.len() }
    }

    /// The points left out of the statistics.
    pub fn left_out(&self) -> usize {
        self.obstructed.iter().filter(|o| o.is_some()).count()
    }
}

/// [`read_grids_cut_by`] for each field of `lits` under its own light (`GridReading::each`):
/// per field, its readings of every grid.
pub fn read_grids_each(
    grids: &[Grid],
    model: &Model,
    lits: &[Lit],
    by: &[&Field],
    progress: &dyn Progress,
) -> Vec<Vec<GridReading>> {
    progress.begin("grid points", grids.iter().map(|g| g.points().len() as u64).sum());
    let mut readings: Vec<Vec<GridReading>> = vec![Vec::with_capacity(grids.len()); lits.len()];
    for g in grids {
        readings.iter_mut().zip(GridReading::each(g, model, lits, by, progress)).for_each(|(r, g)| r.push(g));
    }
    progress.end();
    readings
}

/// Reads every grid of a scene from a solved field, telling `progress` of each point.
pub fn read_grids(grids: &[Grid], model: &Model, field: &Field, progress: &dyn Progress) -> Vec<GridReading> {
    read_grids_cut_by(grids, model, field, &[], progress)
}

/// [`read_grids`], the gathers cut along shadow edges by the rules of the fields `by`
/// ([`GridReading::cut_by`]).
pub fn read_grids_cut_by(
    grids: &[Grid],
    model: &Model,
    field: &Field,
    by: &[&Field],
    progress: &dyn Progress,
) -> Vec<GridReading> {
    read_grids_each(grids, model, &[Lit::own(model, field)], by, progress).swap_remove(0)
}
