//! The uniform kernel's scaling: the case assembled and solved at several patch sizes
//! (time, peak memory, unknowns), the growth exponent fitted to `time ∝ N^p`, and the
//! assembly's speed-up from one thread to all.

use super::error::BenchError;
use super::peak::Peak;
use crate::kernel::Factored;
use crate::model::Model;
use crate::progress::Silent;
use crate::scene::Scene;
use crate::solve::{SolveParams, successive_approximation};
use serde::Serialize;
use std::time::Instant;

/// One size of the scaling curve.
#[derive(Debug, Clone, Serialize)]
pub struct Step {
    /// The patch size, m.
    pub patch_size: f64,
    /// Patches N.
    pub patches: usize,
    /// Unknowns (patches × direction cells).
    pub unknowns: usize,
    /// Non-zeros of `G`.
    pub nonzeros: usize,
    /// Facing pairs assembled.
    pub pairs: usize,
    /// The model's build, s.
    pub assembly_seconds: f64,
    /// The solve (Neumann to 1e-8), s.
    pub solve_seconds: f64,
    /// Peak resident memory during the step above the resident memory before it (VmHWM
    /// reset before the step), bytes; `None` off Linux.
    pub peak_bytes: Option<f64>,
}

/// The curve: its steps by N, and the fitted exponent of time against N.
#[derive(Debug, Clone)]
pub struct Scaling {
    /// The steps, sorted by the number of patches.
    pub steps: Vec<Step>,
    /// `p` of `assembly + solve time ∝ N^p`.
    pub exponent: f64,
}

/// Assembles and solves `scene` at `patch_size`.
pub fn step(scene: &Scene, patch_size: f64) -> Result<(Step, Model), BenchError> {
    let peak = Peak::start();
    let mut scene = scene.clone();
    scene.discretization.patch_size = patch_size;
    let (model, assembly_seconds, solve_seconds) = build_and_solve(&scene)?;
    let step = Step {
        patch_size,
        patches: model.mesh.len(),
        unknowns: model.l0.len(),
        nonzeros: model.kernel.g.nnz(),
        pairs: model.stats.pairs,
        assembly_seconds,
        solve_seconds,
        peak_bytes: peak.bytes(),
    };
    Ok((step, model))
}

/// The model of `scene` built, then solved by Neumann to 1e-8: the model, and the seconds
/// of the build and of the solve.
pub(super) fn build_and_solve(scene: &Scene) -> Result<(Model, f64, f64), BenchError> {
    let t = Instant::now();
    let model = Model::build(scene, &Silent)?;
    let build = t.elapsed().as_secs_f64();
    let t = Instant::now();
    let params = SolveParams { tolerance: 1e-8, max_iterations: 10_000, ..SolveParams::default() };
    successive_approximation(&Factored::new(&model.kernel), &model.l0, &params, &mut |_, _| {})?;
    Ok((model, build, t.elapsed().as_secs_f64()))
}

/// Assembly and solve at several patch sizes (`sizes`, default 2.5, 2, 1.5 and 1.25 times
/// the case's) beside the case's own step `full`, with the fitted exponent.
pub fn scaling(scene: &Scene, sizes: &[f64], full: Step) -> Result<Scaling, BenchError> {
    let sizes = if sizes.is_empty() {
        [2.5, 2.0, 1.5, 1.25].map(|f| f * scene.discretization.patch_size).to_vec()
    } else {
        sizes.to_vec()
    };
    let mut steps = Vec::new();
    for h in sizes {
        steps.push(step(scene, h)?.0);
    }
    steps.push(full);
    steps.sort_by_key(|s| s.patches);
    let exponent = slope(steps.iter().map(|s| (s.patches as f64, s.assembly_seconds + s.solve_seconds)));
    Ok(Scaling { steps, exponent })
}

/// Growth exponent `p` of `y ∝ x^p`: the least-squares slope of `ln y` against `ln x`.
pub(super) fn slope(xy: impl Iterator<Item = (f64, f64)>) -> f64 {
    let points: Vec<(f64, f64)> = xy.map(|(x, y)| (x.ln(), y.ln())).collect();
    let n = points.len() as f64;
    let (mx, my) = (points.iter().map(|p| p.0).sum::<f64>() / n, points.iter().map(|p| p.1).sum::<f64>() / n);
    let sxy: f64 = points.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    let sxx: f64 = points.iter().map(|p| (p.0 - mx).powi(2)).sum();
    sxy / sxx
}

/// Seconds to build the model of `scene` in a pool of `threads` threads.
pub fn assembly_with_threads(scene: &Scene, threads: usize) -> Result<f64, BenchError> {
    let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build()?;
    pool.install(|| {
        let t = Instant::now();
        Model::build(scene, &Silent)?;
        Ok(t.elapsed().as_secs_f64())
    })
}
