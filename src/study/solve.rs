//! The solve of a case (`docs/design.md` §4, §6), as `ugo solve`, `norms` and `compare` run it:
//! the model, every method asked for on `x = L0 + K x` (in the full cell basis or a
//! factored angular one), the reference run, and every readout of its field: patch
//! illuminance, energy balance, probes, grids, reflection orders, norms, the leading
//! eigenpairs of `K` (`solve/arnoldi.rs`) and, on request, each run's agreement with a forward Monte Carlo estimate of the same discretization.

use super::daylight_alone::daylight_readings;
use super::error::StudyError;
use super::kernel::model_with_kernel;
use super::light_scenes::{GroupSolves, solve_light_scenes};
use crate::basis::{Basis, Factorization, Reduced};
use crate::io::{MonteCarlo, Run, Solution};
use crate::kernel::{Explicit, Factored, Kernel, TooLarge};
use crate::model::Model;
use crate::progress::Progress;
use crate::readout::energy::EnergyBalance;
use crate::readout::field::Field;
use crate::readout::illuminance::{arriving, patch_illuminance};
use crate::readout::readings::{Readings, read_field, read_unbarred};
use crate::scene::Scene;
use crate::solve::norms::Norms;
use crate::solve::orders::{OrderRecord, reflection_orders};
use crate::solve::{ArnoldiParams, Method, SolveError, SolveParams, System, arnoldi, relative_residual, solve};
use crate::trace::{TraceOptions, World, agreement, trace_photons};
use std::path::PathBuf;

/// What a command asks of the solve.
#[derive(Debug, Clone)]
pub struct Job {
    /// Methods to run; empty means the case's `[solver] method`.
    pub methods: Vec<Method>,
    /// The stopping rule and memory limit of every run.
    pub params: SolveParams,
    /// Reflection orders whose partial sums are recorded (`None`: 1, 8, 64 with `neumann`).
    pub orders: Option<Vec<usize>>,
    /// Compute the norms of `K` (`ugo norms`, `--norms`).
    pub norms: bool,
    /// The eigenvalues of largest magnitude of `K` to compute, with their eigenvectors.
    pub spectrum: Option<usize>,
    /// Solve for the coefficients of this angular basis instead of the cell values.
    pub basis: Option<Basis>,
    /// Photons of a forward Monte Carlo reference to compare every run with.
    pub photons: Option<u64>,
    /// Seed of that reference.
    pub seed: u64,
    /// Reuse the uniform `G` saved in this file (`--kernel-file`, `super::kernel`).
    pub kernel_file: Option<PathBuf>,
    /// Keep the kernel's fingerprint so that the output saves it (`--save-kernel`).
    pub save_kernel: bool,
    /// Refuse, before the solve, a case with a warning that the model alone shows
    /// (`--strict`; `super::warnings::before_solve`).
    pub strict: bool,
}

impl Default for Job {
    /// The case's own method with the default stopping rule, no extras.
    fn default() -> Job {
        Job {
            methods: Vec::new(),
            params: SolveParams::default(),
            orders: None,
            norms: false,
            spectrum: None,
            basis: None,
            photons: None,
            seed: 1,
            kernel_file: None,
            save_kernel: false,
            strict: false,
        }
    }
}

/// Builds the model of `scene` and solves it as `job` asks, its light scenes too;
/// `progress` hears of the assembly, each method's iterations, the photons and the groups.
pub fn solve_case(scene: &Scene, job: &Job, progress: &dyn Progress) -> Result<Solution, StudyError> {
    let methods = if job.methods.is_empty() { vec![scene.solver.method] } else { job.methods.clone() };
    let (model, kernel) = model_with_kernel(scene, job.kernel_file.as_deref(), job.save_kernel, progress)?;
    if job.strict {
        let found: Vec<_> = super::warnings::before_solve(scene, &model).into_iter().filter(|w| !w.is_note()).collect();
        if !found.is_empty() {
            return Err(StudyError::Strict(found));
        }
    }
    let factors =
        job.basis.map(|b| Factorization::new(b, &model.kernel.blocks, &model.kernel.directions)).transpose()?;
    let reduced = factors.as_ref().map(|f| Reduced::new(&model.kernel, f));
    let (explicit, refused) = explicit_product(&model.kernel, reduced.as_ref(), job, &methods, scene)?;
    let factored = Factored::new(&model.kernel);
    let areas: Vec<f64> = model.mesh.patches.iter().map(|p| p.exposed).collect();
    let source = reduced.as_ref().map(|r| r.source(&model.l0));
    let system = match (&reduced, &source) {
        (Some(r), Some(s)) => System { operator: r, explicit: explicit.as_ref(), areas: &[], l0: s },
        _ => System::of(&model.kernel, &factored, explicit.as_ref(), &areas, &model.l0),
    };
    let locate = |e| crate::model::locate(e, scene, &model.mesh, system.l0.len());
    let (mut runs, failures) = run_methods(&methods, &system, &job.params, &locate, progress)?;
    let reference = reference_run(&runs);
    let coefficients = runs[reference].1.clone();
    let field_of = |y: &[f64]| reduced.as_ref().map_or_else(|| y.to_vec(), |r| r.field(&model.l0, y));
    let x = field_of(&coefficients);
    let scale = x.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    for (run, y) in &mut runs {
        run.difference = y.iter().zip(&coefficients).fold(0.0f64, |m, (a, b)| m.max((a - b).abs())) / scale;
    }
    let monte_carlo = job.photons.map(|photons| {
        let fields: Vec<Vec<f64>> = runs.iter().map(|(_, y)| field_of(y)).collect();
        forward_reference(scene, &model, photons, job.seed, &fields, progress)
    });
    crate::interrupt::check(|| "the forward reference's photons".to_string())?;
    let basis = factors.map(|f| (f, relative_residual(&factored, &model.l0, &x)));
    let orders = order_record(job, &methods, &model);
    let count = job.spectrum.or(refused.is_some().then_some(RHO_PAIRS));
    let spectrum = count.map(|count| arnoldi(&factored, &ArnoldiParams::largest(count))).transpose()?;
    let norms = match (refused, &spectrum) {
        (Some(refused), Some(spectrum)) => Some(Norms::matrix_free(&factored, spectrum, refused)?),
        _ => explicit.as_ref().filter(|_| job.norms).map(Norms::of),
    };
    crate::interrupt::check(|| "the norms' power iterations".to_string())?;
    let spectrum = spectrum.filter(|_| job.spectrum.is_some());
    let runs = runs.into_iter().map(|(r, _)| r).collect();
    let k = model.kernel.cells();
    let field = Field::from_unknowns(&x, k);
    let illuminance = patch_illuminance(&arriving(&model, &x), k);
    let energy = EnergyBalance::of(&model, &x, scene.surfaces.len());
    // With light scenes the case's own light is every group at factor 1, and its error bars
    // are the groups' residual samples summed (set below), not gathered a third time.
    let scenes = !scene.lighting.scenes.is_empty();
    let read = if scenes { read_unbarred } else { read_field };
    let Readings { probes, grids, grid_errors, observers, glare_grids } = read(scene, &model, &field, progress);
    crate::interrupt::check(|| {
        "the readouts (probes, error bars, observers, glare grids, grid points and their error bars)".to_string()
    })?;
    let mut solved = Solution {
        model,
        params: job.params,
        runs,
        reference,
        failures,
        coefficients,
        x,
        basis,
        field,
        illuminance,
        energy,
        probes,
        observers,
        glare_grids,
        grids,
        grid_errors,
        daylight: None,
        orders,
        norms,
        spectrum,
        monte_carlo,
        warnings: Vec::new(),
        kernel,
        light_scenes: None,
    };
    solved.warnings = super::physics_warnings(scene, &solved.model, &solved.x, &solved.energy);
    let how = GroupSolves { method: solved.runs[solved.reference].method, params: job.params, warm: true };
    let readings = (solved.probes.as_slice(), solved.grids.as_slice());
    solved.daylight = daylight_readings(scene, &mut solved.model, readings, &how, progress)?;
    if scenes {
        let light_scenes = solve_light_scenes(scene, &mut solved.model, &solved.x, &how, progress)?;
        if let Some(shared) = &light_scenes.shared {
            let (_, samples) = shared.of_light_scene(&vec![1.0; scene.lighting.groups.len()]);
            solved.grid_errors = samples.bars(&mut solved.probes, &solved.grids);
        }
        solved.light_scenes = Some(light_scenes);
    }
    Ok(solved)
}

/// Leading eigenvalues computed for `ρ(K)` when the norms are matrix-free and no spectrum
/// was asked for: two, so that a `−ρ` as large as `ρ` (two facing plates) is resolved too.
const RHO_PAIRS: usize = 2;

/// The explicit product (of the reduced operator in a basis) when a method or the norms need
/// it. A refusal (over the memory limit) that only the norms met, in the full cell basis, is
/// returned instead of raised: the norms are then computed without it (`Norms::matrix_free`).
fn explicit_product(
    kernel: &Kernel,
    reduced: Option<&Reduced>,
    job: &Job,
    methods: &[Method],
    scene: &Scene,
) -> Result<(Option<Explicit>, Option<TooLarge>), StudyError> {
    let limit = scene.discretization.memory_limit;
    let methods_need = methods.iter().any(Method::needs_explicit);
    if !(job.norms || methods_need) {
        return Ok((None, None));
    }
    match reduced.map_or_else(|| kernel.explicit(limit), |r| r.explicit(limit)) {
        Ok(product) => Ok((Some(Explicit(product)), None)),
        Err(refused) if !methods_need && reduced.is_none() => Ok((None, Some(refused))),
        Err(refused) => Err(refused.into()),
    }
}

/// Every method on `system`: the runs that succeeded with their unknowns, and the failures
/// (an error when every method failed; the one method's own error when only one ran; a
/// stop asked for by a signal at once). `locate` names the place of a value out of range.
#[allow(clippy::type_complexity)]
fn run_methods(
    methods: &[Method],
    system: &System,
    params: &SolveParams,
    locate: &dyn Fn(SolveError) -> SolveError,
    progress: &dyn Progress,
) -> Result<(Vec<(Run, Vec<f64>)>, Vec<(Method, SolveError)>), StudyError> {
    let (mut runs, mut failures) = (Vec::new(), Vec::new());
    for &method in methods {
        progress.begin(&method.name(), params.max_iterations as u64);
        let result =
            solve(method, system, params, &mut |n, r| progress.at(n as u64, &format!("{} {r:.1e}", method.name())));
        progress.end();
        match result.map_err(locate) {
            Ok((x, info)) => runs.push((Run { method, info, difference: 0.0 }, x)),
            Err(e) if methods.len() == 1 || matches!(e, SolveError::Interrupted(_)) => return Err(e.into()),
            Err(e) => failures.push((method, e)),
        }
    }
    if runs.is_empty() {
        return Err(StudyError::EveryMethodFailed(failures));
    }
    Ok((runs, failures))
}

/// `direct` if it ran, else the run with the smallest final residual.
fn reference_run(runs: &[(Run, Vec<f64>)]) -> usize {
    runs.iter().position(|(r, _)| r.method == Method::Direct).unwrap_or_else(|| {
        (0..runs.len()).min_by(|&a, &b| runs[a].0.info.residual().total_cmp(&runs[b].0.info.residual())).unwrap_or(0)
    })
}

/// The partial sums asked for (1, 8 and 64 by default with `neumann`); none in a basis.
fn order_record(job: &Job, methods: &[Method], model: &Model) -> Option<OrderRecord> {
    if job.basis.is_some() || model.l0.iter().all(|&l| l == 0.0) {
        return None;
    }
    let orders = match &job.orders {
        Some(o) => o.clone(),
        None if methods.contains(&Method::Neumann) => vec![1, 8, 64],
        None => return None,
    };
    Some(reflection_orders(&Factored::new(&model.kernel), &model.l0, &orders))
}

fn forward_reference(
    scene: &Scene,
    model: &Model,
    photons: u64,
    seed: u64,
    fields: &[Vec<f64>],
    progress: &dyn Progress,
) -> MonteCarlo {
    let world = World::new(scene, model.mesh.clone());
    progress.begin("photons", photons);
    let options = TraceOptions { seed, max_order: None };
    let estimate = trace_photons(&world, &model.kernel.directions, photons, &options, &|n| progress.advance(n));
    progress.end();
    let agreements = fields.iter().map(|x| agreement(x, &estimate.luminance, &estimate.luminance_error)).collect();
    MonteCarlo { photons, seconds: estimate.seconds, agreements }
}
