//! Restarted GMRES(m) on `(I − K) x = L0`, matrix-free (Saad & Schultz 1986): Arnoldi with
//! modified Gram–Schmidt and Givens rotations, `x_0 = L0`. The Arnoldi residual estimate is
//! the same relative residual as every other method; a restart cycle that gains less than
//! 0.1 % is reported as stagnation.

use super::LinOp;
use super::algorithm::Algorithm;
use super::history::History;
use super::history::residual_norm;
use super::outcome::{SolveError, SolveInfo, SolveParams, dot};

/// Solves `x = L0 + K x` by GMRES with restart length `params.restart`.
pub fn gmres(
    kernel: &dyn LinOp,
    l0: &[f64],
    params: &SolveParams,
    progress: &mut dyn FnMut(usize, f64),
) -> Result<(Vec<f64>, SolveInfo), SolveError> {
    let n = l0.len();
    let m = params.restart.max(1);
    let mut history = History::start(Algorithm::Gmres, l0)?;
    let scale = history.scale;
    let mut x = l0.to_vec();
    let mut w = vec![0.0; n];
    let mut applications = 0;
    let mut iterations = 0;
    let mut basis: Vec<Vec<f64>> = (0..=m).map(|_| vec![0.0; n]).collect();
    let mut h = vec![vec![0.0; m]; m + 1];
    let (mut cs, mut sn, mut g) = (vec![0.0; m], vec![0.0; m], vec![0.0; m + 1]);
    loop {
        // r = L0 − (I − K) x = L0 + K x − x
        let beta = residual_norm(kernel, l0, &x, &mut w);
        applications += 1;
        let cycle_start = history.record(beta / scale, applications, &w)?;
        progress(iterations, cycle_start);
        if cycle_start <= params.tolerance {
            return Ok((x, history.finish(iterations)));
        }
        for ((b, wi), (l, xi)) in basis[0].iter_mut().zip(&w).zip(l0.iter().zip(&x)) {
            *b = (l + wi - xi) / beta;
        }
        g.iter_mut().for_each(|v| *v = 0.0);
        g[0] = beta;
        let mut used = 0;
        for j in 0..m {
            // w = (I − K) v_j
            kernel.apply(&basis[j], &mut w);
            applications += 1;
            iterations += 1;
            for (wi, vi) in w.iter_mut().zip(&basis[j]) {
                *wi = vi - *wi;
            }
            for i in 0..=j {
                let hij = dot(&w, &basis[i]);
                h[i][j] = hij;
                for (wi, vi) in w.iter_mut().zip(&basis[i]) {
                    *wi -= hij * vi;
                }
            }
            let norm_w = dot(&w, &w).sqrt();
            h[j + 1][j] = norm_w;
            for i in 0..j {
                let t = cs[i] * h[i][j] + sn[i] * h[i + 1][j];
                h[i + 1][j] = -sn[i] * h[i][j] + cs[i] * h[i + 1][j];
                h[i][j] = t;
            }
            let r = h[j][j].hypot(h[j + 1][j]);
            (cs[j], sn[j]) = (h[j][j] / r, h[j + 1][j] / r);
            h[j][j] = r;
            h[j + 1][j] = 0.0;
            g[j + 1] = -sn[j] * g[j];
            g[j] *= cs[j];
            used = j + 1;
            let estimate = history.record(g[j + 1].abs() / scale, applications, &w)?;
            progress(iterations, estimate);
            if estimate <= params.tolerance || norm_w <= 1e-300 || iterations >= params.max_iterations {
                break;
            }
            for (b, wi) in basis[j + 1].iter_mut().zip(&w) {
                *b = wi / norm_w;
            }
        }
        // x += V y, H y = g
        let mut y = vec![0.0; used];
        for i in (0..used).rev() {
            y[i] = (g[i] - (i + 1..used).map(|k| h[i][k] * y[k]).sum::<f64>()) / h[i][i];
        }
        for (i, yi) in y.iter().enumerate() {
            for (xk, vk) in x.iter_mut().zip(&basis[i]) {
                *xk += yi * vk;
            }
        }
        let reached = history.last();
        if iterations >= params.max_iterations && reached > params.tolerance {
            let residual = residual_norm(kernel, l0, &x, &mut w) / scale;
            return Err(SolveError::NoConvergence {
                iterations,
                residual,
                tolerance: params.tolerance,
                ratio: f64::NAN,
                needed: f64::NAN,
            });
        }
        if reached > params.tolerance && reached > 0.999 * cycle_start {
            return Err(SolveError::Stagnation { method: "GMRES", iterations, residual: reached });
        }
    }
}
