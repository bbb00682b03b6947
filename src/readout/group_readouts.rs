//! What every light scene reads of its groups (`docs/light-scenes.md`, "Readings shared by
//! the light scenes"; `docs/design.md` §1, §5 and (5.5), (5.6)): each group's grid readings
//! and residual samples, read on the model relit by the group alone with every gather cut
//! along shadow edges as any group's field asks (`cut.rs`), so that a light scene's are
//! exactly `Σ_g f_{s,g}` of its groups' (`docs/design.md` §1: the field and its sources are
//! linear in the factors, and so is a gather in given pieces). Only the bar's formula, which
//! is not linear, is applied per light scene (`residual_samples.rs`).

use super::grid::GridReading;
use super::probe::ProbeReading;
use super::residual_samples::ResidualSamples;
use crate::model::Model;
use crate::scene::Grid;

/// Every group's readings shared by the light scenes.
#[derive(Debug, Clone, PartialEq)]
pub struct GroupReadouts {
    /// Per group, its reading of every grid.
    pub grids: Vec<Vec<GridReading>>,
    /// Per group, its residual samples at the probes, then at its grids' counted points.
    pub samples: Vec<ResidualSamples>,
}

impl GroupReadouts {
    /// The readouts of `values` (per group, every point of `grids` in turn, its
    /// illuminance and its direct part, lx) and `samples` (per group) on `model`; `None`
    /// when they are not as many as the groups or the points.
    pub fn stored(
        grids: &[Grid],
        model: &Model,
        values: Vec<Vec<f64>>,
        samples: Vec<ResidualSamples>,
    ) -> Option<GroupReadouts> {
        let points: Vec<usize> = grids.iter().map(|g| g.points().len()).collect();
        let total = 2 * points.iter().sum::<usize>();
        if values.len() != samples.len() || values.iter().any(|v| v.len() != total) {
            return None;
        }
        let unread: Vec<GridReading> =
            grids.iter().zip(&points).map(|(g, &n)| GridReading::with(g, model, vec![0.0; n], vec![0.0; n])).collect();
        let group = |v: Vec<f64>| {
            let mut start = 0;
            let read = |r: &GridReading| {
                let pairs = &v[start..start + 2 * r.points.len()];
                start += pairs.len();
                let (illuminance, direct) = pairs.chunks(2).map(|p| (p[0], p[1])).unzip();
                GridReading { illuminance, direct, ..r.clone() }
            };
            unread.iter().map(read).collect()
        };
        Some(GroupReadouts { grids: values.into_iter().map(group).collect(), samples })
    }

    /// Per group, every grid's points in turn, their illuminance and direct part (lx): as
    /// [`GroupReadouts::stored`] takes them.
    pub fn values(&self) -> Vec<Vec<f64>> {
        let pairs =
            |r: &GridReading| -> Vec<f64> { r.illuminance.iter().zip(&r.direct).flat_map(|(e, d)| [*e, *d]).collect() };
        self.grids.iter().map(|grids| grids.iter().flat_map(pairs).collect()).collect()
    }

    /// Whether these are the readouts of `groups` groups at the probes `probes` read.
    pub fn fits(&self, groups: usize, probes: &[ProbeReading]) -> bool {
        let count = |g: &Vec<GridReading>| ResidualSamples::count(probes, g);
        self.grids.len() == groups
            && self.samples.len() == groups
            && self.grids.iter().zip(&self.samples).all(|(g, s)| s.0.len() == count(g))
    }

    /// The grid readings and residual samples of the light scene of `factors` (one per
    /// group): `Σ_g f_g` of the groups'.
    pub fn of_light_scene(&self, factors: &[f64]) -> (Vec<GridReading>, ResidualSamples) {
        let count = self.grids.first().map_or(0, Vec::len);
        let grid = |i: usize| {
            let parts: Vec<(f64, &GridReading)> =
                factors.iter().copied().zip(self.grids.iter().map(|g| &g[i])).collect();
            GridReading::superpose(&parts)
        };
        let grids = (0..count).filter_map(grid).collect();
        let parts: Vec<(f64, &ResidualSamples)> = factors.iter().copied().zip(&self.samples).collect();
        (grids, ResidualSamples::superpose(&parts))
    }
}
