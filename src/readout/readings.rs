//! The readouts of one field on a model (`docs/design.md` §5): its probes and grids with their
//! error bars and the UGR at its observers and glare grids, read alike for the case's own field, for
//! each light scene and by `ugo readout` after the solve. The bars follow from the field's
//! residual samples (`residual_samples.rs`), a light scene's from its groups'.

use super::field::Field;
use super::glare_grid::{GlareGridReading, read_glare_grids};
use super::grid::{GridReading, read_grids};
use super::grid_error::GridErrorBars;
use super::grid_ugr::GlareReadings;
use super::probe::{ProbeReading, read_probes};
use super::residual_samples::ResidualSamples;
use super::ugr::{UgrReading, read_observers};
use crate::model::Model;
use crate::progress::Progress;
use crate::scene::Scene;

/// What the `[[probe]]`, `[[grid]]`, `[[observer]]` and `[[glare_grid]]` tables of a case read of one field.
pub struct Readings {
    /// The `[[probe]]` readings, with their error bars.
    pub probes: Vec<ProbeReading>,
    /// The `[[grid]]` readings.
    pub grids: Vec<GridReading>,
    /// Their error bars, one per grid.
    pub grid_errors: Vec<GridErrorBars>,
    /// The UGR at the `[[observer]]`s.
    pub observers: Vec<UgrReading>,
    /// The UGR on the `[[glare_grid]]`s.
    pub glare_grids: Vec<GlareGridReading>,
}

/// The readings of `field` on `model` (lit as the field was) at the tables of `scene`.
pub fn read_field(scene: &Scene, model: &Model, field: &Field, progress: &dyn Progress) -> Readings {
    let mut readings = read_unbarred(scene, model, field, progress);
    let samples = ResidualSamples::of(&readings.probes, &readings.grids, model, field, &[], progress);
    readings.set_bars(&samples);
    readings
}

/// [`read_field`] without the error bars (no probe's `error`, no `grid_errors`), to be
/// set from the field's residual samples ([`Readings::set_bars`]).
pub fn read_unbarred(scene: &Scene, model: &Model, field: &Field, progress: &dyn Progress) -> Readings {
    let probes = read_probes(&scene.probes, model, field, progress);
    let observers = read_observers(&scene.observers, model, field);
    let glare_grids = read_glare_grids(&scene.glare_grids, model, field);
    let grids = read_grids(&scene.grids, model, field, progress);
    Readings { probes, grids, grid_errors: Vec::new(), observers, glare_grids }
}

impl Readings {
    /// Sets the probes' and the grids' error bars from `samples`, the residual samples of
    /// the field read at them.
    pub fn set_bars(&mut self, samples: &ResidualSamples) {
        self.grid_errors = samples.bars(&mut self.probes, &self.grids);
    }

    /// Its observers' and glare grids' readings, which its grids' UGR is taken from.
    pub fn glare(&self) -> GlareReadings<'_> {
        GlareReadings { observers: &self.observers, glare_grids: &self.glare_grids }
    }
}
