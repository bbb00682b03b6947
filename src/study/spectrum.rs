//! What the leading eigenvalues of `K` predict about convergence (`docs/design.md` §4), against
//! what the runs measured: successive approximation contracts the error by `|λ₁| = ρ(K)`
//! per product with `K`; GMRES on `I − K`, once its first steps have removed the isolated
//! Perron eigenvalue `1 − λ₁`, by about `|λ₂|`, so the gap `|λ₂/λ₁|` is its gain per
//! product over successive approximation. When every computed eigenvalue is real (a
//! diffuse kernel is similar to a symmetric one), GMRES does better still: its residual
//! polynomial is bounded by the Chebyshev rate `(√κ − 1)/(√κ + 1)` of the interval
//! `[1 − λ₁, 1 − λ_min]` holding the spectrum of `I − K`, `κ = (1 − λ_min)/(1 − λ₁)`, where
//! `λ_min` is the most negative computed eigenvalue or `−|λ_N|`, whichever is lower (every
//! eigenvalue not computed is smaller than `|λ_N|` in magnitude). In successive
//! approximation the residual is `Kⁿ r₀`, so the ratio of successive residuals tends to
//! `|λ₁|` with an error shrinking like `|λ₂/λ₁|ⁿ`: the gap sets how soon the rate settles.

use crate::io::Run;
use crate::solve::{Method, Spectrum};

/// Relative residual below which a history counts as past its transient.
const TAIL: f64 = 1e-2;

/// One run's measured rate and the spectrum's prediction of it.
#[derive(Debug, Clone, PartialEq)]
pub struct Rate {
    /// The run's method.
    pub method: Method,
    /// Geometric mean contraction of the residual per product with `K` over the tail of
    /// the history (from the first residual below 1e-2 to the last).
    pub measured: f64,
    /// `|λ₁|` for successive approximation, `|λ₂|` for GMRES, NaN for other methods or
    /// when the spectrum holds one eigenvalue only.
    pub predicted: f64,
    /// The Chebyshev rate of the real spectrum's interval, for GMRES; NaN for other methods
    /// or when a computed eigenvalue is complex.
    pub interval: f64,
    /// Products with `K` and relative residual where the tail starts.
    pub start: (usize, f64),
    /// Products with `K` at the last record.
    pub end: usize,
}

/// The measured and predicted rate of every run.
pub fn rates(spectrum: &Spectrum, runs: &[Run]) -> Vec<Rate> {
    let magnitude = |j: usize| spectrum.pairs.get(j).map_or(f64::NAN, |p| p.magnitude());
    runs.iter()
        .map(|run| {
            let (predicted, interval) = match run.method {
                Method::Neumann => (magnitude(0), f64::NAN),
                Method::Gmres { .. } => (magnitude(1), chebyshev_rate(spectrum)),
                _ => (f64::NAN, f64::NAN),
            };
            let (r, a) = (&run.info.residual_history, &run.info.application_history);
            let (start, end) = tail(run).unwrap_or((0, 0));
            let at = |i: usize| a.get(i).copied().unwrap_or(0);
            Rate {
                method: run.method,
                measured: measured_rate(run),
                predicted,
                interval,
                start: (at(start), r.get(start).copied().unwrap_or(f64::NAN)),
                end: at(end),
            }
        })
        .collect()
}

/// `(√κ − 1)/(√κ + 1)` for the interval `[1 − λ₁, 1 − λ_min]`; NaN when a computed
/// eigenvalue is complex or `λ₁ ≥ 1`.
pub fn chebyshev_rate(spectrum: &Spectrum) -> f64 {
    let pairs = &spectrum.pairs;
    let (Some(first), Some(last)) = (pairs.first(), pairs.last()) else { return f64::NAN };
    if pairs.iter().any(|p| p.im != 0.0) || first.re >= 1.0 {
        return f64::NAN;
    }
    let lowest = pairs.iter().map(|p| p.re).fold(-last.magnitude(), f64::min);
    let kappa = (1.0 - lowest) / (1.0 - first.re);
    (kappa.sqrt() - 1.0) / (kappa.sqrt() + 1.0)
}

/// `(r_end / r_start)^(1 / products)` over the tail of `run`'s history; NaN when the
/// history has no two records with products between them.
pub fn measured_rate(run: &Run) -> f64 {
    let (r, a) = (&run.info.residual_history, &run.info.application_history);
    match tail(run) {
        Some((start, end)) if a[end] > a[start] && r[start] > 0.0 && r[end] > 0.0 => {
            (r[end] / r[start]).powf(1.0 / (a[end] - a[start]) as f64)
        }
        _ => f64::NAN,
    }
}

/// The first and last record of the tail: from the first residual below 1e-2 (if at
/// least two products remain after it, else from the first record) to the last.
fn tail(run: &Run) -> Option<(usize, usize)> {
    let (r, a) = (&run.info.residual_history, &run.info.application_history);
    let end = r.len().min(a.len()).checked_sub(1)?;
    let start = r[..=end].iter().position(|&x| x <= TAIL).filter(|&s| a[end] > a[s] + 1).unwrap_or(0);
    Some((start, end))
}
