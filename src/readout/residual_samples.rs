//! The residual samples of one field at a case's probes and grids (`docs/design.md` (5.5),
//! (5.6)): what the error bars of its readings are computed from, probe after probe
//! (`error_bar::probe_samples`), then grid after grid (`grid_error::grid_samples`).
//!
//! A sample, `π (L_gathered − L_h)` at the point a bar's direction meets, is linear in the
//! field and its sources for given pieces of the gathers, and the point's albedo is
//! geometry alone. So a light scene's samples are `Σ_g f_{s,g} samples_g` of its groups'
//! (`docs/design.md` §1): the groups' rays are traced once for every light scene, and only
//! the bar's formula (5.5), which is not linear, is applied per light scene
//! (`docs/light-scenes.md`, "Error bars of light scenes").

use super::error_bar::{Sample, probe_rays, probe_samples, set_errors};
use super::field::Field;
use super::grid::GridReading;
use super::grid_error::{GridErrorBars, grid_rays, grids_samples};
use super::lit::Lit;
use super::probe::ProbeReading;
use crate::model::Model;
use crate::progress::Progress;

/// A field's residual samples at a case's probes, then its grids' counted points.
#[derive(Debug, Clone, PartialEq)]
pub struct ResidualSamples(pub Vec<Sample>);

impl ResidualSamples {
    /// The samples of `field` on `model` (lit as the field was) at the probes and grids
    /// of `probes` and `grids` (readings of any field: only where they read is used), the
    /// gathers cut by the field's own rule or, for fields to be summed, by the rules of all
    /// of them, `by` (`cut.rs`), telling `progress` of each probe and counted point; a
    /// signal's stop leaves the samples after it zero (`crate::interrupt`: the caller checks).
    pub fn of(
        probes: &[ProbeReading],
        grids: &[GridReading],
        model: &Model,
        field: &Field,
        by: &[&Field],
        progress: &dyn Progress,
    ) -> ResidualSamples {
        ResidualSamples::of_each(probes, grids, model, &[Lit::own(model, field)], by, progress).swap_remove(0)
    }

    /// [`ResidualSamples::of`] for each field of `lits` under its own light, every direction's
    /// gather shared among them (`lit.rs`), cut by the rules of `by` (of all of `lits` when
    /// it names none).
    pub fn of_each(
        probes: &[ProbeReading],
        grids: &[GridReading],
        model: &Model,
        lits: &[Lit],
        by: &[&Field],
        progress: &dyn Progress,
    ) -> Vec<ResidualSamples> {
        let at_probes = probe_samples(probes, model, lits, by, progress);
        let at_grids = grids_samples(grids, model, lits, by, progress);
        let joined = |(mut all, at_grids): (Vec<Sample>, Vec<Sample>)| {
            all.extend(at_grids);
            ResidualSamples(all)
        };
        at_probes.into_iter().zip(at_grids).map(joined).collect()
    }

    /// How many samples the readings `probes` and `grids` take.
    pub fn count(probes: &[ProbeReading], grids: &[GridReading]) -> usize {
        probes.iter().map(probe_rays).sum::<usize>() + grids.iter().map(grid_rays).sum::<usize>()
    }

    /// `Σ w·S` over the `(w, S)` of `parts` (the samples of one case's tables, each of one
    /// group's field): the samples of the field `Σ w x`. The albedo, geometry alone, is
    /// the first part's.
    pub fn superpose(parts: &[(f64, &ResidualSamples)]) -> ResidualSamples {
        let Some((_, first)) = parts.first() else { return ResidualSamples(Vec::new()) };
        let mut sum: Vec<Sample> = first.0.iter().map(|s| Sample { illuminance: 0.0, ..*s }).collect();
        for (w, part) in parts {
            sum.iter_mut().zip(&part.0).for_each(|(s, p)| s.illuminance += w * p.illuminance);
        }
        ResidualSamples(sum)
    }

    /// Sets the error bars of `probes` and returns those of `grids` (the readings these
    /// samples were taken at, of the field they are of); samples missing read as zero.
    pub fn bars(&self, probes: &mut [ProbeReading], grids: &[GridReading]) -> Vec<GridErrorBars> {
        set_errors(probes, &self.0);
        let mut start = probes.iter().map(probe_rays).sum::<usize>();
        let mut bars = Vec::with_capacity(grids.len());
        for grid in grids {
            let n = grid_rays(grid);
            let own = self.0.get(start..start + n).map_or_else(|| vec![Sample::default(); n], <[Sample]>::to_vec);
            bars.push(GridErrorBars::from_samples(grid, &own));
            start += n;
        }
        bars
    }
}
