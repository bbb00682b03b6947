//! Norms of the kernel and of `I − K` (`docs/design.md` §4): `‖K‖₁`, `‖K‖∞`, `‖K‖_F` exactly
//! from the explicit matrix; `‖K‖₂` by power iteration on `KᵀK`; the spectral radius
//! `ρ(K)` (the Perron root, `K ≥ 0`) by power iteration on `K + I` (the shift keeps the
//! Perron root strictly dominant even when `K` is periodic, as between two plates), each
//! with its own convergence check; and the condition number `cond∞(I − K)`, exact rather
//! than estimated: for `ρ(K) < 1`, `(I − K)⁻¹ = Σ Kⁿ ≥ 0`, so `‖(I − K)⁻¹‖∞` is the largest
//! entry of `(I − K)⁻¹ 1`, one linear solve (GMRES).
//!
//! When the explicit product is over the memory limit (the office's hierarchy: 18 GiB),
//! the same norms without it, matrix-free on the factored operator, exact for `K ≥ 0`
//! (every block non-negative, checked; `G ≥ 0`): `‖K‖∞ = max (K 1)`, `‖K‖₁ = max (Kᵀ 1)`
//! (`Kᵀ = Gᵀ Bᵀ`), `ρ(K)` the largest magnitude of the leading eigenvalues by Arnoldi
//! (`solve/arnoldi.rs`: the Perron root is real and largest, and power iteration would
//! crawl where `−ρ` and `0.97 ρ` are eigenvalues too), `cond∞(I − K)` by the same one
//! GMRES solve; `‖K‖_F` needs every entry and `‖K‖₂` the serial `Kᵀ` thousands of times,
//! so neither is computed, and `ρ(K) ≤ ‖K‖₂ ≤ √(‖K‖₁ ‖K‖∞)` bounds the latter.

use super::arnoldi::{Eigenpair, Spectrum};
use super::gmres;
use super::linop::LinOp;
use super::outcome::SolveParams;
use crate::kernel::{Explicit, Factored, TooLarge, spmv};

/// Norms of `K` and what they predict.
#[derive(Debug, Clone, PartialEq)]
pub struct Norms {
    /// `‖K‖₁`, the largest column sum of `|K|`.
    pub one: f64,
    /// `‖K‖∞`, the largest row sum of `|K|`.
    pub infinity: f64,
    /// `‖K‖_F`, the square root of the sum of squares; `None` matrix-free.
    pub frobenius: Option<f64>,
    /// `‖K‖₂`, by power iteration on `KᵀK`; `None` matrix-free.
    pub two: Option<Estimate>,
    /// The spectral radius `ρ(K)`, by power iteration on `K + I` or, matrix-free, by Arnoldi.
    pub spectral_radius: Estimate,
    /// `cond∞(I − K)`; NaN when `ρ(K) ≥ 1` or the solve failed.
    pub condition_infinity: f64,
    /// The refusal of the explicit product that made them matrix-free; `None` when computed
    /// from it.
    pub matrix_free: Option<TooLarge>,
}

/// A value from an iteration and whether its convergence check passed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Estimate {
    /// The estimated value.
    pub value: f64,
    /// Applications of the operator spent (power iterations, or Arnoldi's products).
    pub iterations: usize,
    /// Whether the iteration's convergence check passed.
    pub converged: bool,
    /// The iteration.
    pub by: Estimator,
}

/// The iteration behind an [`Estimate`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Estimator {
    /// Power iteration: the relative change per iteration below 1e-12.
    Power,
    /// Thick-restart Arnoldi: the eigen-residual below its tolerance times `|θ₁|`.
    Arnoldi,
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
        let one = largest(&columns);
        let spectral_radius = spectral_radius(k);
        let condition_infinity = condition(k, infinity, spectral_radius.value);
        let frobenius = Some(frobenius.sqrt());
        Norms {
            one,
            infinity,
            frobenius,
            two: Some(two_norm(k)),
            spectral_radius,
            condition_infinity,
            matrix_free: None,
        }
    }

    /// The norms of `k` without its explicit product, refused as `refused`, with `ρ(K)` from
    /// its leading eigenvalues `spectrum`: exact for `K ≥ 0`, so `refused` stands (`Err`)
    /// when some material block is negative.
    pub fn matrix_free(k: &Factored, spectrum: &Spectrum, refused: TooLarge) -> Result<Norms, TooLarge> {
        if !k.kernel().is_nonnegative() {
            return Err(refused);
        }
        let ones = vec![1.0; k.dim()];
        let mut sums = vec![0.0; k.dim()];
        k.apply(&ones, &mut sums);
        let infinity = largest(&sums);
        k.apply_transposed(&ones, &mut sums);
        let one = largest(&sums);
        let spectral_radius = Estimate {
            value: spectrum.pairs.first().map_or(0.0, Eigenpair::magnitude),
            iterations: spectrum.applications,
            converged: spectrum.converged,
            by: Estimator::Arnoldi,
        };
        let condition_infinity = condition(k, infinity, spectral_radius.value);
        let matrix_free = Some(refused);
        Ok(Norms { one, infinity, frobenius: None, two: None, spectral_radius, condition_infinity, matrix_free })
    }

    /// `√(‖K‖₁ ‖K‖∞)`, the upper bound of `‖K‖₂`.
    pub fn two_bound(&self) -> f64 {
        (self.one * self.infinity).sqrt()
    }

    /// Successive-approximation iterations to reach `tolerance`: `log(tol)/log ρ(K)`.
    pub fn predicted_iterations(&self, tolerance: f64) -> f64 {
        tolerance.ln() / self.spectral_radius.value.ln()
    }
}

fn largest(v: &[f64]) -> f64 {
    v.iter().copied().fold(0.0, f64::max)
}

fn spectral_radius(k: &Explicit) -> Estimate {
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

fn two_norm(k: &Explicit) -> Estimate {
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
fn power(n: usize, mut apply: impl FnMut(&[f64], &mut [f64]), shift: f64) -> Estimate {
    let mut v = vec![1.0 / (n as f64).sqrt(); n];
    let mut w = vec![0.0; n];
    let mut previous = f64::NAN;
    for iteration in (1..=POWER_MAX).take_while(|_| !crate::interrupt::asked()) {
        apply(&v, &mut w);
        let lambda = w.iter().map(|x| x * x).sum::<f64>().sqrt();
        if lambda == 0.0 {
            return Estimate { value: 0.0, iterations: iteration, converged: true, by: Estimator::Power };
        }
        v.iter_mut().zip(&w).for_each(|(vi, wi)| *vi = wi / lambda);
        if (lambda - previous).abs() <= POWER_TOLERANCE * lambda {
            return Estimate { value: lambda + shift, iterations: iteration, converged: true, by: Estimator::Power };
        }
        previous = lambda;
    }
    Estimate { value: previous + shift, iterations: POWER_MAX, converged: false, by: Estimator::Power }
}

/// `(1 + ‖K‖∞) ‖(I − K)⁻¹‖∞` for `ρ(K) = rho < 1`, else NaN.
fn condition(k: &dyn LinOp, infinity: f64, rho: f64) -> f64 {
    if rho >= 1.0 {
        return f64::NAN;
    }
    let ones = vec![1.0; k.dim()];
    let params = SolveParams { tolerance: 1e-12, max_iterations: 5000, restart: 50, ..SolveParams::default() };
    match gmres(k, &ones, &params, &mut |_, _| {}) {
        Ok((y, _)) => (1.0 + infinity) * largest(&y),
        Err(_) => f64::NAN,
    }
}
