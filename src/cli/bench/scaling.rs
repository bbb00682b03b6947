//! The scaling part of `ugo bench`: the case assembled and solved at several patch sizes
//! (time, peak memory, unknowns), the growth exponent fitted to `time ∝ N^p`, and the
//! assembly's speed-up from one thread to all.

use super::peak::Peak;
use anyhow::Result;
use serde::Serialize;
use std::time::Instant;
use ugo::kernel::Factored;
use ugo::model::Model;
use ugo::progress::Silent;
use ugo::scene::Scene;
use ugo::solve::{SolveParams, successive_approximation};

/// One size of the scaling curve.
#[derive(Debug, Clone, Serialize)]
pub struct Step {
    pub patch_size: f64,
    pub patches: usize,
    pub unknowns: usize,
    pub nonzeros: usize,
    pub pairs: usize,
    pub assembly_seconds: f64,
    pub solve_seconds: f64,
    /// Peak resident memory during the step above the resident memory before it (VmHWM
    /// reset before the step), bytes; `None` off Linux.
    pub peak_bytes: Option<f64>,
}

/// Assembles and solves `scene` at `patch_size`.
pub fn step(scene: &Scene, patch_size: f64) -> Result<(Step, Model)> {
    let peak = Peak::start();
    let mut scene = scene.clone();
    scene.discretization.patch_size = patch_size;
    let t = Instant::now();
    let model = Model::build(&scene, &Silent)?;
    let assembly_seconds = t.elapsed().as_secs_f64();
    let t = Instant::now();
    let params = SolveParams { tolerance: 1e-8, max_iterations: 10_000, ..SolveParams::default() };
    successive_approximation(&Factored::new(&model.kernel), &model.l0, &params, &mut |_, _| {})?;
    let solve_seconds = t.elapsed().as_secs_f64();
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

/// Least-squares slope of `ln(total time)` against `ln N`.
pub fn exponent(steps: &[Step]) -> f64 {
    slope(steps.iter().map(|s| (s.patches as f64, s.assembly_seconds + s.solve_seconds)))
}

/// Growth exponent `p` of `y ∝ x^p`: the least-squares slope of `ln y` against `ln x`.
pub fn slope(xy: impl Iterator<Item = (f64, f64)>) -> f64 {
    let points: Vec<(f64, f64)> = xy.map(|(x, y)| (x.ln(), y.ln())).collect();
    let n = points.len() as f64;
    let (mx, my) = (points.iter().map(|p| p.0).sum::<f64>() / n, points.iter().map(|p| p.1).sum::<f64>() / n);
    let sxy: f64 = points.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    let sxx: f64 = points.iter().map(|p| (p.0 - mx).powi(2)).sum();
    sxy / sxx
}

/// Seconds to build the model of `scene` in a pool of `threads` threads.
pub fn assembly_with_threads(scene: &Scene, threads: usize) -> Result<f64> {
    let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build()?;
    pool.install(|| {
        let t = Instant::now();
        Model::build(scene, &Silent)?;
        Ok(t.elapsed().as_secs_f64())
    })
}
