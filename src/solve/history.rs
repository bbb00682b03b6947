//! The record every solver keeps: relative residual, kernel applications and time per
//! iterate, so that methods compare on the same axes.

use super::outcome::{SolveError, SolveInfo, norm};
use std::time::Instant;

pub struct History {
    start: Instant,
    /// `‖L0‖₂`: residuals are relative to it.
    pub scale: f64,
    residuals: Vec<f64>,
    applications: Vec<usize>,
    times: Vec<f64>,
}

impl History {
    /// Starts the record of a solve of `x = L0 + K x`; a zero source has nothing to solve.
    pub fn start(l0: &[f64]) -> Result<History, SolveError> {
        let scale = norm(l0);
        if scale == 0.0 {
            return Err(SolveError::NoSource);
        }
        Ok(History { start: Instant::now(), scale, residuals: Vec::new(), applications: Vec::new(), times: Vec::new() })
    }

    /// Records the relative residual of the current iterate; returns it.
    pub fn record(&mut self, relative_residual: f64, applications: usize) -> f64 {
        self.residuals.push(relative_residual);
        self.applications.push(applications);
        self.times.push(self.start.elapsed().as_secs_f64());
        relative_residual
    }

    pub fn last(&self) -> f64 {
        self.residuals.last().copied().unwrap_or(f64::NAN)
    }

    /// Geometric mean of the last `window` residual ratios (NaN before there are enough).
    pub fn mean_ratio(&self, window: usize) -> f64 {
        let h = &self.residuals;
        if h.len() <= window {
            return f64::NAN;
        }
        (h[h.len() - 1] / h[h.len() - 1 - window]).powf(1.0 / window as f64)
    }

    pub fn finish(self, method: &'static str, iterations: usize) -> SolveInfo {
        SolveInfo {
            method,
            iterations,
            applications: self.applications.last().copied().unwrap_or(0),
            residual_history: self.residuals,
            application_history: self.applications,
            time_history: self.times,
            seconds: self.start.elapsed().as_secs_f64(),
        }
    }
}

/// `‖L0 + K x − x‖₂` with one kernel application into `scratch`.
pub fn residual_norm(kernel: &dyn super::LinOp, l0: &[f64], x: &[f64], scratch: &mut [f64]) -> f64 {
    kernel.apply(x, scratch);
    scratch.iter().zip(l0).zip(x).map(|((k, l), x)| (l + k - x) * (l + k - x)).sum::<f64>().sqrt()
}

/// The relative residual `‖L0 + K x − x‖₂ / ‖L0‖₂` of any `x` (e.g. a field rebuilt from
/// basis coefficients, measured in the full system).
pub fn relative_residual(kernel: &dyn super::LinOp, l0: &[f64], x: &[f64]) -> f64 {
    residual_norm(kernel, l0, x, &mut vec![0.0; x.len()]) / norm(l0)
}
