//! The readouts of one field on a model (`docs/design.md` §5): its probes and grids with their
//! error bars and the UGR at its observers, read alike for the case's own field, for
//! each light scene and by `ugo readout` after the solve.

use super::error_bar::estimate_errors;
use super::field::Field;
use super::grid::{GridReading, read_grids};
use super::grid_error::{GridErrorBars, grid_errors};
use super::probe::{ProbeReading, read_probes};
use super::ugr::{UgrReading, read_observers};
use crate::model::Model;
use crate::progress::Progress;
use crate::scene::Scene;

/// What the `[[probe]]`, `[[grid]]` and `[[observer]]` tables of a case read of one field.
pub struct Readings {
    /// The `[[probe]]` readings, with their error bars.
    pub probes: Vec<ProbeReading>,
    /// The `[[grid]]` readings.
    pub grids: Vec<GridReading>,
    /// Their error bars, one per grid.
    pub grid_errors: Vec<GridErrorBars>,
    /// The UGR at the `[[observer]]`s.
    pub observers: Vec<UgrReading>,
}

/// The readings of `field` on `model` (lit as the field was) at the tables of `scene`.
pub fn read_field(scene: &Scene, model: &Model, field: &Field, progress: &dyn Progress) -> Readings {
    let mut probes = read_probes(&scene.probes, model, field, progress);
    estimate_errors(&mut probes, model, field, progress);
    let observers = read_observers(&scene.observers, model, field);
    let grids = read_grids(&scene.grids, model, field, progress);
    let grid_errors = grid_errors(&grids, model, field, progress);
    Readings { probes, grids, grid_errors, observers }
}
