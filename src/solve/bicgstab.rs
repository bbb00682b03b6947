//! BiCGSTAB on `(I − K) x = L0`, matrix-free (van der Vorst 1992), `x_0 = L0`; two kernel
//! applications per iteration. Breakdown (`ρ = 0` or `ω = 0`) is reported, not hidden.

use super::LinOp;
use super::algorithm::Algorithm;
use super::history::History;
use super::history::residual_norm;
use super::outcome::{SolveError, SolveInfo, SolveParams, dot};

/// Solves `x = L0 + K x` by BiCGSTAB.
pub fn bicgstab(
    kernel: &dyn LinOp,
    l0: &[f64],
    params: &SolveParams,
    progress: &mut dyn FnMut(usize, f64),
) -> Result<(Vec<f64>, SolveInfo), SolveError> {
    let n = l0.len();
    let mut history = History::start(Algorithm::Bicgstab, l0)?;
    let scale = history.scale;
    let a = |v: &[f64], out: &mut [f64]| {
        kernel.apply(v, out);
        out.iter_mut().zip(v).for_each(|(o, vi)| *o = vi - *o);
    };
    let mut x = l0.to_vec();
    let mut r = vec![0.0; n];
    let mut residual = residual_norm(kernel, l0, &x, &mut r);
    for ((ri, l), xi) in r.iter_mut().zip(l0).zip(&x) {
        *ri = l + *ri - xi;
    }
    let mut applications = 1;
    progress(0, history.record(residual / scale, applications, &r)?);
    let r_hat = r.clone();
    let (mut p, mut v, mut s, mut t) = (vec![0.0; n], vec![0.0; n], vec![0.0; n], vec![0.0; n]);
    let (mut rho, mut alpha, mut omega) = (1.0, 1.0, 1.0);
    for iteration in 1..=params.max_iterations {
        if residual / scale <= params.tolerance {
            return Ok((x, history.finish(iteration - 1)));
        }
        let rho_next = dot(&r_hat, &r);
        if rho_next == 0.0 || omega == 0.0 {
            return Err(SolveError::Breakdown { method: "BiCGSTAB", iterations: iteration, why: "ρ or ω vanished" });
        }
        let beta = (rho_next / rho) * (alpha / omega);
        rho = rho_next;
        for ((pi, ri), vi) in p.iter_mut().zip(&r).zip(&v) {
            *pi = ri + beta * (*pi - omega * vi);
        }
        a(&p, &mut v);
        alpha = rho / dot(&r_hat, &v);
        for ((si, ri), vi) in s.iter_mut().zip(&r).zip(&v) {
            *si = ri - alpha * vi;
        }
        a(&s, &mut t);
        applications += 2;
        let tt = dot(&t, &t);
        omega = if tt > 0.0 { dot(&t, &s) / tt } else { 0.0 };
        for (((xi, pi), si), (ri, ti)) in x.iter_mut().zip(&p).zip(&s).zip(r.iter_mut().zip(&t)) {
            *xi += alpha * pi + omega * si;
            *ri = si - omega * ti;
        }
        residual = dot(&r, &r).sqrt();
        progress(iteration, history.record(residual / scale, applications, &r)?);
    }
    Err(SolveError::NoConvergence {
        iterations: params.max_iterations,
        residual: history.last(),
        tolerance: params.tolerance,
        ratio: f64::NAN,
        needed: f64::NAN,
    })
}
