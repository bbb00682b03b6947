//! Successive approximation `x_{n+1} = L0 + K x_n`, `x_0 = L0`: the reflection-order
//! (Neumann) expansion, `x_n = Σ_{m≤n} K^m L0` (`design.md` §4).
//!
//! Divergence is detected from the residual ratio: for `ρ(K) ≥ 1` it tends to a value
//! `≥ 1` instead of `ρ(K) < 1`, and the method stops with a clear error rather than loop.

use super::{SolveError, SolveInfo, SolveParams, norm};
use crate::kernel::LinOp;
use std::time::Instant;

/// Iterations over which the residual ratio is averaged to detect divergence.
const WINDOW: usize = 10;

/// Solves `x = L0 + K x` by successive approximation. `progress(n, residual)` is called
/// after each iteration.
pub fn successive_approximation(
    kernel: &dyn LinOp,
    l0: &[f64],
    params: &SolveParams,
    progress: &mut dyn FnMut(usize, f64),
) -> Result<(Vec<f64>, SolveInfo), SolveError> {
    let start = Instant::now();
    let scale = norm(l0);
    if scale == 0.0 {
        return Err(SolveError::NoSource);
    }
    let mut x = l0.to_vec();
    let mut next = vec![0.0; l0.len()];
    let mut history = Vec::new();
    for n in 0..=params.max_iterations {
        kernel.apply(&x, &mut next);
        let mut sq = 0.0;
        for ((y, &l), &xi) in next.iter_mut().zip(l0).zip(&x) {
            *y += l;
            sq += (*y - xi) * (*y - xi);
        }
        let residual = sq.sqrt() / scale;
        history.push(residual);
        progress(n, residual);
        if residual <= params.tolerance {
            let info = SolveInfo {
                method: "successive approximation",
                iterations: n,
                applications: n + 1,
                residual_history: history,
                seconds: start.elapsed().as_secs_f64(),
            };
            return Ok((x, info));
        }
        let ratio = mean_ratio(&history);
        if n >= 2 * WINDOW && ratio > 1.0 - 1e-6 {
            return Err(SolveError::Diverges { ratio, iterations: n, residual });
        }
        std::mem::swap(&mut x, &mut next);
    }
    let residual = history.last().copied().unwrap_or(f64::NAN);
    let ratio = mean_ratio(&history);
    let needed = if ratio < 1.0 { (params.tolerance / residual).ln() / ratio.ln() } else { f64::INFINITY };
    Err(SolveError::NoConvergence {
        iterations: params.max_iterations,
        residual,
        tolerance: params.tolerance,
        ratio,
        needed: needed.ceil(),
    })
}

/// Geometric mean of the last `WINDOW` residual ratios.
fn mean_ratio(history: &[f64]) -> f64 {
    if history.len() <= WINDOW {
        return f64::NAN;
    }
    let last = history[history.len() - 1];
    let first = history[history.len() - 1 - WINDOW];
    (last / first).powf(1.0 / WINDOW as f64)
}
