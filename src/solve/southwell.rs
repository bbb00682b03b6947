//! Progressive refinement (Southwell iteration, Cohen et al. 1988) for the one-cell
//! (radiosity) case: repeatedly shoot the unshot luminance `ΔL_j` of the patch with the
//! most unshot flux `A_j ΔL_j` into every patch, `L_i += K_ij ΔL_j`. The invariant
//! `x = L0 + K(x − ΔL)` makes the residual `K ΔL`, evaluated after every `N` shots (one
//! application's worth of work, counted as one kernel application, plus one for the check).

use super::algorithm::Algorithm;
use super::history::History;
use super::history::residual_norm;
use super::outcome::{SolveError, SolveInfo, SolveParams};
use crate::kernel::Explicit;

/// Solves `x = L0 + K x` by shooting; `k` is the explicit product `B·G`, `areas` the patch areas.
pub fn southwell(
    k: &Explicit,
    areas: &[f64],
    l0: &[f64],
    params: &SolveParams,
    progress: &mut dyn FnMut(usize, f64),
) -> Result<(Vec<f64>, SolveInfo), SolveError> {
    let n = l0.len();
    if areas.len() != n {
        return Err(SolveError::Unsupported { method: "Southwell", needs: "one direction cell (K = 1)" });
    }
    let mut history = History::start(Algorithm::Southwell, l0)?;
    let scale = history.scale;
    let columns = k.0.to_csc();
    let mut x = l0.to_vec();
    let mut unshot = l0.to_vec();
    let mut scratch = vec![0.0; n];
    let mut applications = 0;
    for sweep in 0..=params.max_iterations {
        applications += 1;
        let residual = history.record(residual_norm(k, l0, &x, &mut scratch) / scale, applications, &scratch)?;
        progress(sweep, residual);
        if residual <= params.tolerance {
            return Ok((x, history.finish(sweep)));
        }
        for _ in 0..n {
            let j = (0..n).max_by(|&a, &b| (areas[a] * unshot[a]).total_cmp(&(areas[b] * unshot[b]))).unwrap_or(0);
            let shot = std::mem::take(&mut unshot[j]);
            if let Some(column) = columns.outer_view(j) {
                for (i, &kij) in column.iter() {
                    x[i] += kij * shot;
                    unshot[i] += kij * shot;
                }
            }
        }
        applications += 1;
    }
    Err(SolveError::NoConvergence {
        iterations: params.max_iterations,
        residual: history.last(),
        tolerance: params.tolerance,
        ratio: history.mean_ratio(10),
        needed: f64::NAN,
    })
}
