//! The one record of a solved case (`docs/design.md` §6, §8): what `study::solve_case`
//! returns and `write_solution` writes as it is. The command line prints from it.

use super::warning::Warning;
use crate::basis::Factorization;
use crate::model::{Change, Fingerprint, Model};
use crate::readout::daylight::DaylightReadings;
use crate::readout::energy::EnergyBalance;
use crate::readout::field::Field;
use crate::readout::glare_grid::GlareGridReading;
use crate::readout::grid::GridReading;
use crate::readout::grid_error::GridErrorBars;
use crate::readout::grid_ugr::GlareReadings;
use crate::readout::probe::ProbeReading;
use crate::readout::ugr::UgrReading;
use crate::solve::norms::Norms;
use crate::solve::orders::OrderRecord;
use crate::solve::{Method, SolveError, SolveInfo, SolveParams, Spectrum};
use crate::trace::Agreement;
use std::path::PathBuf;

/// A case solved: its model, every run, the field and every readout of it.
pub struct Solution {
    /// The discretized system the field solves.
    pub model: Model,
    /// The stopping rule the runs were held to.
    pub params: SolveParams,
    /// Every method that ran on the system (one for `solve`, several for `compare`).
    pub runs: Vec<Run>,
    /// The run whose field is kept: `direct` if it ran, else the smallest final residual.
    pub reference: usize,
    /// Methods that failed while others succeeded.
    pub failures: Vec<(Method, SolveError)>,
    /// The reference run's unknowns (basis coefficients in a reduced solve).
    pub coefficients: Vec<f64>,
    /// The field `x[i·K + k]`, cd/m².
    pub x: Vec<f64>,
    /// The factored basis of a reduced solve, and the field's residual in the full system.
    pub basis: Option<(Factorization, f64)>,
    /// The field per patch and cell.
    pub field: Field,
    /// Illuminance of each patch, lx.
    pub illuminance: Vec<f64>,
    /// Where the flux went, lm.
    pub energy: EnergyBalance,
    /// The `[[probe]]` readings.
    pub probes: Vec<ProbeReading>,
    /// The UGR at the `[[observer]]`s.
    pub observers: Vec<UgrReading>,
    /// The UGR on the `[[glare_grid]]`s.
    pub glare_grids: Vec<GlareGridReading>,
    /// The `[[grid]]` readings.
    pub grids: Vec<GridReading>,
    /// Their error bars, one per grid.
    pub grid_errors: Vec<GridErrorBars>,
    /// SC, ERC, IRC and DF at the probes and grids, under a `[sky]`.
    pub daylight: Option<DaylightReadings>,
    /// The reflection-order record, when taken.
    pub orders: Option<OrderRecord>,
    /// Norms of the kernel, when computed.
    pub norms: Option<Norms>,
    /// The leading eigenpairs of the full `K` (`--spectrum N`).
    pub spectrum: Option<Spectrum>,
    /// Each run's agreement with a forward Monte Carlo estimate, when asked for.
    pub monte_carlo: Option<MonteCarlo>,
    /// What the solved field says is probably not meant (`study::physics_warnings`).
    pub warnings: Vec<Warning>,
    /// The kernel file read, and the fingerprint to save.
    pub kernel: KernelRecord,
    /// The fields of the case's light scenes and of their groups, when it has any.
    pub light_scenes: Option<super::LightScenes>,
}

impl Solution {
    /// What the reference run's solve did.
    pub fn info(&self) -> &SolveInfo {
        &self.runs[self.reference].info
    }

    /// Its observers' and glare grids' readings, which its grids' UGR is taken from.
    pub fn glare(&self) -> GlareReadings<'_> {
        GlareReadings { observers: &self.observers, glare_grids: &self.glare_grids }
    }
}

/// One method's solve of the system, for comparison.
#[derive(Debug, Clone)]
pub struct Run {
    /// The method run.
    pub method: Method,
    /// What its solve did.
    pub info: SolveInfo,
    /// Largest relative difference from the reference solution, `max |x − x_ref| / max |x_ref|`.
    pub difference: f64,
}

/// The forward Monte Carlo estimate of the same discretization, and each run's agreement.
pub struct MonteCarlo {
    /// Photons traced.
    pub photons: u64,
    /// Seconds the tracing took.
    pub seconds: f64,
    /// One per run, in the order of the runs.
    pub agreements: Vec<Agreement>,
}

/// Where the kernel of a solve came from, and what to save.
#[derive(Debug, Clone, Default)]
pub struct KernelRecord {
    /// The case's fingerprint, stored in `/kernel` when the kernel is saved.
    pub save: Option<Fingerprint>,
    /// The kernel file `G` was read from, when it was.
    pub loaded: Option<Loaded>,
}

/// A kernel read from a file instead of assembled.
#[derive(Debug, Clone)]
pub struct Loaded {
    /// The kernel file.
    pub path: PathBuf,
    /// The parts that changed but only rebuild `B`, `D` or `L0` (`G` reused).
    pub rebuilt: Vec<Change>,
    /// Seconds spent reading the file.
    pub seconds: f64,
    /// True for a hierarchy: its tree and links were refined under the file's
    /// reflectances and luminaires, and are reused as they are.
    pub hierarchical: bool,
}
