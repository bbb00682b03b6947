//! Successive right-hand sides against one kernel (`docs/design.md` §4): `x_j = (I − K)⁻¹ b_j`
//! for a sequence of sources `b_j` (the groups of a case's light scenes), each solve started
//! from the best combination of the solutions already known when that combination is
//! nearly the solution — the projection of Fischer, "Projection techniques for iterative
//! solution of Ax = b with successive right-hand sides", Comput. Methods Appl. Mech.
//! Engrg. 163 (1998) 193–204, in its minimal-residual form.
//!
//! [`Projection`] keeps every known vector `u_i` with its exact image `w_i = (I − K) u_i`
//! (one kernel application each). For a new source `b`, `c = argmin ‖b − W c‖₂` (modified
//! Gram–Schmidt on the images; a column within `1e-10` of the span of the earlier ones is
//! dropped). When that leaves at most [`USEFUL`] of `‖b‖`, the solve starts from
//! `x0 = U c` with the residual `r0 = b − (I − K) x0` (one application): the method solves
//! the correction `δ = r0 + K δ` — the same system with the source `r0` — to the relative
//! residual `tol·‖b‖/‖r0‖`, so that `x = x0 + δ` meets the cold solve's stopping rule
//! `‖b − (I − K) x‖ ≤ tol·‖b‖` (a start already that close is returned as it is).
//! Otherwise it starts cold: a partial projection (a residual of 0.2, say) was measured
//! to cost GMRES more iterations than it saves, the Krylov space of `r0` being no better
//! than that of `b` (docs/light-scenes.md). The last of several groups whose sum is a
//! known solution is thus almost free, and no solve costs more than a cold one. A direct
//! method, and a cold projection (`warm = false`), always start from nothing.

use super::LinOp;
use super::algorithm::Algorithm;
use super::method::{Method, System, solve};
use super::outcome::{SolveError, SolveInfo, SolveParams, norm};

/// A column of the least-squares problem nearly in the span of the earlier ones.
const DEPENDENT: f64 = 1e-10;

/// The largest relative residual of a projected start that replaces a cold one.
pub const USEFUL: f64 = 1e-3;

/// The known solutions of one operator and their images.
pub struct Projection {
    /// Start from the known solutions (else every solve is cold).
    warm: bool,
    known: Vec<Vec<f64>>,
    images: Vec<Vec<f64>>,
}

/// One solve of [`Projection::solve`].
#[derive(Debug, Clone)]
pub struct Successive {
    /// The solution `x = (I − K)⁻¹ b`.
    pub x: Vec<f64>,
    /// The correction's solve; its residuals are relative to `‖b‖`.
    pub info: SolveInfo,
    /// `‖b − (I − K) x0‖/‖b‖` of the start (1 for a cold start).
    pub start: f64,
    /// `‖b − (I − K) x‖/‖b‖` of the solution, evaluated anew.
    pub residual: f64,
    /// Kernel applications, the projection's and the residual's included.
    pub applications: usize,
}

impl Projection {
    /// No known solution yet; `warm` says whether solves start from the known ones.
    pub fn new(warm: bool) -> Projection {
        Projection { warm, known: Vec::new(), images: Vec::new() }
    }

    /// Adds a known vector `u` (any: a solution of another source is the useful kind), at
    /// the cost of one application of `operator`.
    pub fn learn(&mut self, operator: &dyn LinOp, u: Vec<f64>) {
        let image = minus_k(operator, &u);
        self.known.push(u);
        self.images.push(image);
    }

    /// Solves `x = b + K x` for the source `b = system.l0` with `method`, from the best
    /// start the known solutions give, and learns `x`.
    pub fn solve(
        &mut self,
        method: Method,
        system: &System,
        params: &SolveParams,
        progress: &mut dyn FnMut(usize, f64),
    ) -> Result<Successive, SolveError> {
        let b = system.l0;
        let scale = norm(b);
        let direct = matches!(method, Method::Direct | Method::DirectSparse);
        let projected = (self.warm && scale > 0.0 && !direct).then(|| self.start(system.operator, b)).flatten();
        let (x0, r0, mut applications) = projected.unwrap_or_else(|| (vec![0.0; b.len()], b.to_vec(), 0));
        let start = if scale == 0.0 { 0.0 } else { norm(&r0) / scale };
        let (x, info) = if start <= params.tolerance {
            (x0, no_iteration(start))
        } else {
            let correction = System { l0: &r0, ..*system };
            let tolerance = params.tolerance / start;
            let (delta, mut info) = solve(method, &correction, &SolveParams { tolerance, ..*params }, progress)?;
            info.residual_history.iter_mut().for_each(|r| *r *= start);
            (x0.iter().zip(&delta).map(|(a, d)| a + d).collect::<Vec<f64>>(), info)
        };
        applications += info.applications + 1;
        let image = minus_k(system.operator, &x);
        let residual = if scale == 0.0 { 0.0 } else { norm(&sub(b, &image)) / scale };
        self.known.push(x.clone());
        self.images.push(image);
        Ok(Successive { x, info, start, residual, applications })
    }

    /// `x0 = U c` over the known vectors, with `c` minimizing `‖b − W c‖`, its residual
    /// `r0` and the applications spent (one), when `‖b − W c‖ ≤ USEFUL ‖b‖`.
    fn start(&self, operator: &dyn LinOp, b: &[f64]) -> Option<(Vec<f64>, Vec<f64>, usize)> {
        let images: Vec<&[f64]> = self.images.iter().map(Vec::as_slice).collect();
        let (c, left) = least_squares(&images, b);
        if left > USEFUL * norm(b) {
            return None;
        }
        let mut x0 = vec![0.0; b.len()];
        for (u, c) in self.known.iter().zip(&c) {
            x0.iter_mut().zip(u).for_each(|(x, u)| *x += c * u);
        }
        let r0 = sub(b, &minus_k(operator, &x0));
        Some((x0, r0, 1))
    }
}

/// The record of a solve that started within the tolerance: no iteration.
fn no_iteration(residual: f64) -> SolveInfo {
    SolveInfo {
        method: Algorithm::Projection,
        iterations: 0,
        applications: 0,
        residual_history: vec![residual],
        application_history: vec![0],
        time_history: vec![0.0],
        seconds: 0.0,
    }
}

/// `(I − K) u`.
fn minus_k(operator: &dyn LinOp, u: &[f64]) -> Vec<f64> {
    let mut ku = vec![0.0; u.len()];
    operator.apply(u, &mut ku);
    sub(u, &ku)
}

fn sub(a: &[f64], b: &[f64]) -> Vec<f64> {
    a.iter().zip(b).map(|(a, b)| a - b).collect()
}

fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(a, b)| a * b).sum()
}

/// `c = argmin ‖b − Σ c_j a_j‖₂` by modified Gram–Schmidt (twice) on the columns `a_j`,
/// and that least `‖b − Σ c_j a_j‖₂`; a column within [`DEPENDENT`] of the span of the
/// earlier ones gets `c_j = 0`.
fn least_squares(columns: &[&[f64]], b: &[f64]) -> (Vec<f64>, f64) {
    let m = columns.len();
    let mut q: Vec<Vec<f64>> = Vec::new();
    let mut kept: Vec<usize> = Vec::new();
    let mut r = vec![vec![0.0; m]; m];
    for (j, a) in columns.iter().enumerate() {
        let mut v = a.to_vec();
        let mut coefficients = vec![0.0; q.len()];
        for _ in 0..2 {
            for (k, qk) in q.iter().enumerate() {
                let h = dot(qk, &v);
                coefficients[k] += h;
                v.iter_mut().zip(qk).for_each(|(v, q)| *v -= h * q);
            }
        }
        let length = norm(&v);
        // dependent on the basis so far, or not finite: skipped
        if length.partial_cmp(&(DEPENDENT * norm(a))) != Some(std::cmp::Ordering::Greater) {
            continue;
        }
        let row = q.len();
        for (k, h) in coefficients.into_iter().enumerate() {
            r[k][j] = h;
        }
        r[row][j] = length;
        q.push(v.iter().map(|v| v / length).collect());
        kept.push(j);
    }
    let mut left = b.to_vec();
    let mut y = Vec::with_capacity(q.len());
    for qk in &q {
        let h = dot(qk, &left);
        left.iter_mut().zip(qk).for_each(|(l, q)| *l -= h * q);
        y.push(h);
    }
    let mut c = vec![0.0; m];
    for row in (0..kept.len()).rev() {
        let later: f64 = (row + 1..kept.len()).map(|k| r[row][kept[k]] * c[kept[k]]).sum();
        c[kept[row]] = (y[row] - later) / r[row][kept[row]];
    }
    (c, norm(&left))
}
