//! The record every solver keeps: relative residual, kernel applications and time per
//! iterate, so that methods compare on the same axes. Recording an iterate is also where
//! every method stops on a value out of range (a residual that is not finite) and on a
//! signal (`crate::interrupt`).

use super::algorithm::Algorithm;
use super::outcome::{SolveError, SolveInfo, norm};
use super::range::OutOfRange;
use std::time::Instant;

/// The record of one solve: the relative residual, the kernel applications and the time
/// of every iterate.
pub struct History {
    method: Algorithm,
    start: Instant,
    /// `‖L0‖₂`: residuals are relative to it.
    pub scale: f64,
    residuals: Vec<f64>,
    applications: Vec<usize>,
    times: Vec<f64>,
}

impl History {
    /// Starts the record of `method`'s solve of `x = L0 + K x`; a zero source has nothing
    /// to solve, and one whose norm is not finite cannot be solved.
    pub fn start(method: Algorithm, l0: &[f64]) -> Result<History, SolveError> {
        let scale = norm(l0);
        if scale == 0.0 {
            return Err(SolveError::NoSource);
        }
        if !scale.is_finite() {
            return Err(SolveError::OutOfRange(Box::new(OutOfRange::of(
                method,
                None,
                "the source term's norm ‖L0‖₂",
                scale,
                l0,
            ))));
        }
        let (residuals, applications, times) = (Vec::new(), Vec::new(), Vec::new());
        Ok(History { method, start: Instant::now(), scale, residuals, applications, times })
    }

    /// Records the relative residual of the current iterate; returns it. A residual that is
    /// not finite is an error located in `vector` (the iterate, or the vector `K` just
    /// made), and so is a stop asked for by a signal.
    pub fn record(&mut self, relative_residual: f64, applications: usize, vector: &[f64]) -> Result<f64, SolveError> {
        let iteration = self.residuals.len();
        if !relative_residual.is_finite() {
            let range = OutOfRange::of(self.method, Some(iteration), "the residual", relative_residual, vector);
            return Err(SolveError::OutOfRange(Box::new(range)));
        }
        crate::interrupt::check(|| format!("{}, iteration {iteration}", self.method))?;
        self.residuals.push(relative_residual);
        self.applications.push(applications);
        self.times.push(self.start.elapsed().as_secs_f64());
        Ok(relative_residual)
    }

    /// The last recorded relative residual (NaN before the first).
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

    /// The record as the solve's [`SolveInfo`], `iterations` being the iterations it took.
    pub fn finish(self, iterations: usize) -> SolveInfo {
        SolveInfo {
            method: self.method,
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
