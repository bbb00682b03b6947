//! Norms of the kernel and of `I − K` (`docs/design.md` §4): `‖K‖₁`, `‖K‖∞`, `‖K‖_F` exactly
//! from the explicit matrix; `‖K‖₂` by power iteration on `KᵀK`; the spectral radius
//! `ρ(K)` (the Perron root, `K ≥ 0`) by power iteration on `K + I` (the shift keeps the
//! Perron root strictly dominant even when `K` is periodic, as between two plates), each
//! with its own convergence check; and the condition number `cond∞(I − K)`, exact rather
//! than estimated: for `ρ(K) < 1`, `(I − K)⁻¹ = Σ Kⁿ ≥ 0`, so `‖(I − K)⁻¹‖∞` is the largest
//! entry of `(I − K)⁻¹ 1`, one linear solve (GMRES).

use super::gmres;
use super::outcome::SolveParams;
use crate::kernel::{Explicit, spmv};

/// Norms of `K` and what they predict.
#[derive(Debug, Clone, PartialEq)]
pub struct Norms {
    /// `‖K‖₁`, the largest column sum of `|K|`.
    pub one: f64,
    /// `‖K‖∞`, the largest row sum of `|K|`.
    pub infinity: f64,
    /// `‖K‖_F`, the square root of the sum of squares.
    pub frobenius: f64,
    /// `‖K‖₂`, by power iteration on `KᵀK`.
    pub two: PowerEstimate,
    /// The spectral radius `ρ(K)`, by power iteration on `K + I`.
    pub spectral_radius: PowerEstimate,
    /// `cond∞(I − K)`; NaN when `ρ(K) ≥ 1` or the solve failed.
    pub condition_infinity: f64,
}

/// A value from power iteration and whether its convergence check passed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PowerEstimate {
    /// The estimated value.
    pub value: f64,
    /// Power iterations spent.
    pub iterations: usize,
    /// Whether the relative change per iteration fell below the tolerance.
    pub converged: bool,
}

/// Relative change per iteration below which a power iteration has converged.
const POWER_TOLERANCE: f64 = 1e-12;
const POWER_MAX: usize = 20_000;

impl Norms {
    /// Every norm of the explicit product `k`, and `cond∞(I − K)` by one GMRES solve.
    pub fn of(k: &Explicit) -> Norms {
        let m = &k.0;
        let n = m.rows();
        let mut columns = vec![0.0; n];
        let (mut infinity, mut frobenius): (f64, f64) = (0.0, 0.0);
        for row in m.outer_iterator() {
            infinity = infinity.max(row.data().iter().map(|v| v.abs()).sum());
            for (j, v) in row.iter() {
                columns[j] += v.abs();
                frobenius += v * v;
            }
        }
        let one = columns.iter().copied().fold(0.0, f64::max);
        let spectral_radius = spectral_radius(k);
        let condition_infinity = if spectral_radius.value < 1.0 { condition(k, infinity) } else { f64::NAN };
        Norms { one, infinity, frobenius: frobenius.sqrt(), two: two_norm(k), spectral_radius, condition_infinity }
    }

    /// Successive-approximation iterations to reach `tolerance`: `log(tol)/log ρ(K)`.
    pub fn predicted_iterations(&self, tolerance: f64) -> f64 {
        tolerance.ln() / self.spectral_radius.value.ln()
    }
}

fn spectral_radius(k: &Explicit) -> PowerEstimate {
    let n = k.dim();
    power(
        n,
        |v, out| {
            k.apply(v, out);
            out.iter_mut().zip(v).for_each(|(o, x)| *o += x);
        },
        -1.0,
    )
}

fn two_norm(k: &Explicit) -> PowerEstimate {
    let n = k.dim();
    let transpose = k.0.transpose_view().to_csr();
    let mut middle = vec![0.0; n];
    let mut estimate = power(
        n,
        |v, out| {
            spmv(&k.0, v, &mut middle);
            spmv(&transpose, &middle, out);
        },
        0.0,
    );
    estimate.value = estimate.value.sqrt();
    estimate
}

/// Dominant eigenvalue of a non-negative operator by power iteration from the ones
/// vector, minus `shift`'s opposite: returns `λ + shift`. A signal ends the iteration
/// unconverged (`crate::interrupt`: the caller checks).
fn power(n: usize, mut apply: impl FnMut(&[f64], &mut [f64]), shift: f64) -> PowerEstimate {
    let mut v = vec![1.0 / (n as f64).sqrt(); n];
    let mut w = vec![0.0; n];
    let mut previous = f64::NAN;
    for iteration in (1..=POWER_MAX).take_while(|_| !crate::interrupt::asked()) {
        apply(&v, &mut w);
        let lambda = w.iter().map(|x| x * x).sum::<f64>().sqrt();
        if lambda == 0.0 {
            return PowerEstimate { value: 0.0, iterations: iteration, converged: true };
        }
        v.iter_mut().zip(&w).for_each(|(vi, wi)| *vi = wi / lambda);
        if (lambda - previous).abs() <= POWER_TOLERANCE * lambda {
            return PowerEstimate { value: lambda + shift, iterations: iteration, converged: true };
        }
        previous = lambda;
    }
    PowerEstimate { value: previous + shift, iterations: POWER_MAX, converged: false }
}

fn condition(k: &Explicit, infinity: f64) -> f64 {
    let ones = vec![1.0; k.dim()];
    let params = SolveParams { tolerance: 1e-12, max_iterations: 5000, restart: 50, ..SolveParams::default() };
    match gmres(k, &ones, &params, &mut |_, _| {}) {
        Ok((y, _)) => (1.0 + infinity) * y.iter().copied().fold(0.0, f64::max),
        Err(_) => f64::NAN,
    }
}
