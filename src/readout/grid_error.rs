//! A grid's error bars (`docs/design.md` §5, "A grid's error bars", (5.6)): the bar (5.5)
//! of every point that counts, and those of the statistics `E_avg`, `E_min` and `U0` (5.3).
//!
//! A probe's bar costs [`RAYS`](super::error_bar::RAYS) gathers; a grid has hundreds of
//! points. Each point that counts takes [`GRID_RAYS`] stratified cosine-distributed
//! directions of its own (`error_bar::samples`, the probe's estimator), and its bar pools
//! them with those of the counted points at most [`NEIGHBOURS`] cells away along each edge
//! (up to 9 × 4 = 36 samples): `ΔE`, `σ` and `ρ̄` of (5.5) over the pool,
//! with `ΔI = 0` (grid points are not corrected near geometry). The pool's spread holds the
//! neighbours' differences as well as each one's noise, so `σ` is not understated; where
//! the residual changes faster than the spacing (a point by a contact) the pool's mean
//! smooths it. Cost: [`GRID_RAYS`] gathers a counted point, against one for its reading.
//! Chosen on the open box's floor grid among 2–64 directions a point and pools of 1, 3 × 3
//! and 5 × 5 points, held out on the Cornell box's (`docs/accuracy.md`, "Error bars").
//!
//! The statistics' bars, each point's error `e_i` within its bar `δ_i`:
//!
//! * `δE_avg = (1/n) Σ δ_i`: `|Σ e_i|/n ≤ Σ |e_i|/n` whatever the errors' correlation;
//! * `δE_min = max_i (δ_i − (E_i − E_min))`: the exact minimum lies in
//!   `[min_i (E_i − δ_i), min_i (E_i + δ_i)]`, whose lower end is the farther from
//!   `E_min`; only points within their bar of the minimum can be it;
//! * `δU0`: the larger distance from `U0` to the ends of
//!   `[max(0, E_min − δE_min)/(E_avg + δE_avg), (E_min + δE_min)/(E_avg − δE_avg)]`
//!   (infinite once `δE_avg ≥ E_avg`).

use super::error_bar::{Residual, Sample, samples};
use super::field::Field;
use super::grid::GridReading;
use super::lit::Lit;
use crate::model::Model;
use crate::progress::Progress;
use rayon::prelude::*;

/// Directions a counted grid point takes of its own.
pub const GRID_RAYS: usize = 4;

/// A point's bar pools the samples of the counted points at most this many cells away
/// along each edge.
pub const NEIGHBOURS: usize = 1;

/// The error bars of one grid's readings, lx (`u0` dimensionless); NaN where there is none.
#[derive(Debug, Clone, PartialEq)]
pub struct GridErrorBars {
    /// Per point, as `GridReading::illuminance`: NaN for a point left out of the statistics.
    pub points: Vec<f64>,
    /// `δE_avg`.
    pub average: f64,
    /// `δE_min`.
    pub min: f64,
    /// `δU0`.
    pub u0: f64,
}

impl GridErrorBars {
    /// The bars of `grid`, read from `field` on `model`, `progress` advanced by one per
    /// counted point (a signal's stop leaves the rays after it zero: `crate::interrupt`,
    /// the caller checks).
    pub fn of(grid: &GridReading, model: &Model, field: &Field, progress: &dyn Progress) -> GridErrorBars {
        GridErrorBars::from_samples(grid, &grid_samples(grid, model, &[Lit::own(model, field)], &[], progress)[0])
    }

    /// The bars of `grid` from its counted points' samples ([`grid_samples`]).
    pub fn from_samples(grid: &GridReading, samples: &[Sample]) -> GridErrorBars {
        let mut slot = vec![None; grid.points.len()];
        counted(grid).iter().enumerate().for_each(|(k, &i)| slot[i] = Some(k));
        let [nu, nv] = grid.grid.resolution;
        let points = (0..grid.points.len())
            .into_par_iter()
            .map(|i| {
                if slot[i].is_none() {
                    return f64::NAN;
                }
                let (a, b) = (i % nu, i / nu);
                let (us, vs) = (window(a, nu), window(b, nv));
                let pool = vs
                    .flat_map(|v| us.clone().map(move |u| v * nu + u))
                    .filter_map(|j| slot[j])
                    .flat_map(|k| &samples[k * GRID_RAYS..(k + 1) * GRID_RAYS]);
                Residual::pooled(pool).error_bar(0.0)
            })
            .collect();
        statistics(grid, points)
    }
}

/// The residual's samples of the counted points of `grid` ([`GRID_RAYS`] each, point after
/// point) for each field of `lits` on `model` (the gathers shared, cut by the rules of
/// `by`: `error_bar::samples`), `progress` advanced by one per counted point.
pub fn grid_samples(
    grid: &GridReading,
    model: &Model,
    lits: &[Lit],
    by: &[&Field],
    progress: &dyn Progress,
) -> Vec<Vec<Sample>> {
    let receivers: Vec<_> = counted(grid).iter().map(|&i| (grid.points[i], grid.grid.normal)).collect();
    samples(model, lits, &receivers, GRID_RAYS, by, progress)
}

/// The samples of every grid of `readings`, grid after grid, for each field of `lits` (cut
/// by the rules of `by`), telling `progress` of each counted point.
pub fn grids_samples(
    readings: &[GridReading],
    model: &Model,
    lits: &[Lit],
    by: &[&Field],
    progress: &dyn Progress,
) -> Vec<Vec<Sample>> {
    progress.begin("grid error bars", readings.iter().map(|g| counted(g).len() as u64).sum());
    let mut all: Vec<Vec<Sample>> = vec![Vec::new(); lits.len()];
    for grid in readings {
        let each = grid_samples(grid, model, lits, by, progress);
        all.iter_mut().zip(each).for_each(|(all, s)| all.extend(s));
    }
    progress.end();
    all
}

/// The samples the bars of `grid` pool: [`GRID_RAYS`] per counted point.
pub fn grid_rays(grid: &GridReading) -> usize {
    counted(grid).len() * GRID_RAYS
}

/// The points of `grid` its statistics count (not obstructed).
fn counted(grid: &GridReading) -> Vec<usize> {
    (0..grid.points.len()).filter(|&i| grid.obstructed[i].is_none()).collect()
}

/// The cells at most [`NEIGHBOURS`] from `a` of `0..n`.
fn window(a: usize, n: usize) -> std::ops::Range<usize> {
    a.saturating_sub(NEIGHBOURS)..(a + NEIGHBOURS + 1).min(n)
}

/// The bars of `E_avg`, `E_min` and `U0` from the points' bars `points`.
fn statistics(grid: &GridReading, points: Vec<f64>) -> GridErrorBars {
    let st = grid.stats();
    let bars = grid.stats_of(&points);
    let min = points
        .iter()
        .zip(&grid.illuminance)
        .filter(|(d, _)| !d.is_nan())
        .map(|(d, e)| d - (e - st.min))
        .fold(f64::NAN, f64::max);
    let average = bars.average;
    let low = (st.min - min).max(0.0) / (st.average + average);
    let high = if average < st.average { (st.min + min) / (st.average - average) } else { f64::INFINITY };
    let u0 = if st.counted == 0 { f64::NAN } else { (high - st.u0).max(st.u0 - low) };
    GridErrorBars { points, average, min, u0 }
}

/// The error bars of every grid of `readings`, telling `progress` of each counted point.
pub fn grid_errors(
    readings: &[GridReading],
    model: &Model,
    field: &Field,
    progress: &dyn Progress,
) -> Vec<GridErrorBars> {
    progress.begin("grid error bars", readings.iter().map(|g| counted(g).len() as u64).sum());
    let bars = readings.iter().map(|g| GridErrorBars::of(g, model, field, progress)).collect();
    progress.end();
    bars
}
