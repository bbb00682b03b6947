//! What the leading eigenvalues of `K` predict about convergence (`design.md` §4), against
//! what the runs measured: successive approximation contracts the error by `|λ₁| = ρ(K)`
//! per product with `K`; GMRES on `I − K`, once its first steps have removed the isolated
//! Perron eigenvalue `1 − λ₁`, by about `|λ₂|`, so the gap `|λ₂/λ₁|` is its gain per
//! product over successive approximation.

use crate::io::Run;
use crate::solve::{Method, Spectrum};

/// Relative residual below which a history counts as past its transient.
const TAIL: f64 = 1e-2;

/// One run's measured rate and the spectrum's prediction of it.
#[derive(Debug, Clone, PartialEq)]
pub struct Rate {
    pub method: Method,
    /// Geometric mean contraction of the residual per product with `K` over the tail of
    /// the history (from the first residual below 1e-2 to the last).
    pub measured: f64,
    /// `|λ₁|` for successive approximation, `|λ₂|` for GMRES, NaN for other methods or
    /// when the spectrum holds one eigenvalue only.
    pub predicted: f64,
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
            let predicted = match run.method {
                Method::Neumann => magnitude(0),
                Method::Gmres { .. } => magnitude(1),
                _ => f64::NAN,
            };
            let (r, a) = (&run.info.residual_history, &run.info.application_history);
            let (start, end) = tail(run).unwrap_or((0, 0));
            let at = |i: usize| a.get(i).copied().unwrap_or(0);
            Rate {
                method: run.method,
                measured: measured_rate(run),
                predicted,
                start: (at(start), r.get(start).copied().unwrap_or(f64::NAN)),
                end: at(end),
            }
        })
        .collect()
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
