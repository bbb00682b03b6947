//! Successive approximation `x_{n+1} = L0 + K x_n`, `x_0 = L0`: the reflection-order
//! (Neumann) expansion, `x_n = Σ_{m≤n} K^m L0` (`docs/design.md` §4).
//!
//! Divergence is detected from the residual ratio: for `ρ(K) ≥ 1` it tends to a value
//! `≥ 1` instead of `ρ(K) < 1`, and the method stops with a clear error rather than loop.

use super::LinOp;
use super::algorithm::Algorithm;
use super::history::History;
use super::outcome::{SolveError, SolveInfo, SolveParams};

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
    let mut history = History::start(Algorithm::SuccessiveApproximation, l0)?;
    let scale = history.scale;
    let mut x = l0.to_vec();
    let mut next = vec![0.0; l0.len()];
    for n in 0..=params.max_iterations {
        kernel.apply(&x, &mut next);
        let mut sq = 0.0;
        for ((y, &l), &xi) in next.iter_mut().zip(l0).zip(&x) {
            *y += l;
            sq += (*y - xi) * (*y - xi);
        }
        let residual = history.record(sq.sqrt() / scale, n + 1, &next)?;
        progress(n, residual);
        if residual <= params.tolerance {
            return Ok((x, history.finish(n)));
        }
        let ratio = history.mean_ratio(WINDOW);
        if n >= 2 * WINDOW && ratio > 1.0 - 1e-6 {
            return Err(SolveError::Diverges { ratio, iterations: n, residual });
        }
        std::mem::swap(&mut x, &mut next);
    }
    let residual = history.last();
    let ratio = history.mean_ratio(WINDOW);
    let needed = if ratio < 1.0 { (params.tolerance / residual).ln() / ratio.ln() } else { f64::INFINITY };
    Err(SolveError::NoConvergence {
        iterations: params.max_iterations,
        residual,
        tolerance: params.tolerance,
        ratio,
        needed: needed.ceil(),
    })
}
