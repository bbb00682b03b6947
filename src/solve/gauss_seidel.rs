//! Gauss–Seidel sweeps on the explicit product `B·G`: `x_i ← (L0_i + Σ_{j≠i} K_ij x_j)/(1 − K_ii)`
//! in row order, using the newest values (the "gathering" counterpart of the lecture's
//! successive approximation). One sweep costs one kernel application; the residual after
//! each sweep costs another.

use super::algorithm::Algorithm;
use super::history::History;
use super::history::residual_norm;
use super::outcome::{SolveError, SolveInfo, SolveParams};
use crate::kernel::Explicit;

/// Solves `x = L0 + K x` by Gauss–Seidel sweeps over the explicit matrix `k`.
pub fn gauss_seidel(
    k: &Explicit,
    l0: &[f64],
    params: &SolveParams,
    progress: &mut dyn FnMut(usize, f64),
) -> Result<(Vec<f64>, SolveInfo), SolveError> {
    let mut history = History::start(Algorithm::GaussSeidel, l0)?;
    let scale = history.scale;
    let m = &k.0;
    let (indptr, indices, data) = (m.indptr(), m.indices(), m.data());
    let indptr = indptr.raw_storage();
    let mut x = l0.to_vec();
    let mut scratch = vec![0.0; l0.len()];
    let mut applications = 1;
    let mut residual = history.record(residual_norm(k, l0, &x, &mut scratch) / scale, applications, &scratch)?;
    progress(0, residual);
    for sweep in 1..=params.max_iterations {
        if residual <= params.tolerance {
            return Ok((x, history.finish(sweep - 1)));
        }
        for i in 0..x.len() {
            let (mut sum, mut diagonal) = (l0[i], 0.0);
            for (&j, &v) in indices[indptr[i]..indptr[i + 1]].iter().zip(&data[indptr[i]..indptr[i + 1]]) {
                if j == i { diagonal += v } else { sum += v * x[j] }
            }
            x[i] = sum / (1.0 - diagonal);
        }
        applications += 2;
        residual = history.record(residual_norm(k, l0, &x, &mut scratch) / scale, applications, &scratch)?;
        progress(sweep, residual);
    }
    Err(SolveError::NoConvergence {
        iterations: params.max_iterations,
        residual,
        tolerance: params.tolerance,
        ratio: history.mean_ratio(10),
        needed: f64::NAN,
    })
}
