//! Agreement of a deterministic result with a Monte Carlo reference: every difference in
//! units of the reference's standard error, `z = (x − m)/σ`, and a summary.
//!
//! If `x` were the reference's expectation, `z` would be about standard normal: mean 0,
//! rms 1, `|z| > 3` for 0.27 % of the values. A systematic deviation (discretization
//! error, a bug) shows as an rms well above 1 once `σ` is smaller than it; the relative
//! differences `‖x − m‖/‖m‖` (L1 and L2) measure its size, and `‖σ‖₂/‖m‖₂` the
//! reference's own noise on the same scale. Since `E‖x − m‖² = ‖x − E m‖² + ‖σ‖²` for
//! independent errors, `√(‖x − m‖² − ‖σ‖²)/‖m‖` is the L2 difference with the reference's
//! noise taken out: the error of `x` itself, even when the noise is not negligible.

use std::fmt;

/// The summary of `z` over the compared values.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Agreement {
    /// Values compared (those with a positive standard error).
    pub compared: usize,
    /// Values skipped because the reference has no sample there (`σ = 0`), and of those
    /// the ones where `x` differs from the reference.
    pub unsampled: usize,
    /// Of the `unsampled`, those where `x` differs from the reference.
    pub unsampled_different: usize,
    /// Mean of `z = (x − m)/σ` over the compared values.
    pub mean_z: f64,
    /// Root mean square of `z`.
    pub rms_z: f64,
    /// Largest `|z|`.
    pub max_abs_z: f64,
    /// Fraction of the compared values with `|z| > 3`.
    pub beyond_3: f64,
    /// `Σ|x − m| / Σ|m|` and `‖x − m‖₂/‖m‖₂` over every value.
    pub relative_l1: f64,
    /// `‖x − m‖₂/‖m‖₂` over every value.
    pub relative_l2: f64,
    /// `‖σ‖₂/‖m‖₂`: the reference's noise on the scale of `relative_l2`.
    pub noise_l2: f64,
    /// `√(max(‖x − m‖₂² − ‖σ‖₂², 0))/‖m‖₂`: the L2 difference less the reference's noise.
    pub excess_l2: f64,
}

/// Compares `values` with the reference `mean ± error` (all the same length).
pub fn agreement(values: &[f64], mean: &[f64], error: &[f64]) -> Agreement {
    let mut a = Agreement {
        compared: 0,
        unsampled: 0,
        unsampled_different: 0,
        mean_z: 0.0,
        rms_z: 0.0,
        max_abs_z: 0.0,
        beyond_3: 0.0,
        relative_l1: 0.0,
        relative_l2: 0.0,
        noise_l2: 0.0,
        excess_l2: 0.0,
    };
    let (mut sum_z, mut sum_z2, mut beyond) = (0.0, 0.0, 0usize);
    let (mut l1, mut l1_ref, mut l2, mut l2_ref, mut noise) = (0.0, 0.0, 0.0, 0.0, 0.0);
    for ((&x, &m), &s) in values.iter().zip(mean).zip(error) {
        let d = x - m;
        l1 += d.abs();
        l1_ref += m.abs();
        l2 += d * d;
        l2_ref += m * m;
        noise += s * s;
        if s > 0.0 {
            let z = d / s;
            a.compared += 1;
            sum_z += z;
            sum_z2 += z * z;
            a.max_abs_z = a.max_abs_z.max(z.abs());
            beyond += usize::from(z.abs() > 3.0);
        } else {
            a.unsampled += 1;
            a.unsampled_different += usize::from(d.abs() > 1e-12 * m.abs().max(x.abs()));
        }
    }
    if a.compared > 0 {
        let c = a.compared as f64;
        (a.mean_z, a.rms_z, a.beyond_3) = (sum_z / c, (sum_z2 / c).sqrt(), beyond as f64 / c);
    }
    if l2_ref > 0.0 {
        (a.relative_l1, a.relative_l2, a.noise_l2) = (l1 / l1_ref, (l2 / l2_ref).sqrt(), (noise / l2_ref).sqrt());
        a.excess_l2 = ((l2 - noise).max(0.0) / l2_ref).sqrt();
    }
    a
}

impl fmt::Display for Agreement {
    /// `N compared (M unsampled), mean z, rms z, max |z|, beyond 3σ %, relative L1, noise L2`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{} compared ({} unsampled), mean z {:+.3}, rms z {:.3}, max |z| {:.2}, beyond 3σ {:.2} %, relative L1 \
             difference {:.2e}, noise L2 {:.2e}",
            self.compared,
            self.unsampled,
            self.mean_z,
            self.rms_z,
            self.max_abs_z,
            100.0 * self.beyond_3,
            self.relative_l1,
            self.noise_l2
        )
    }
}
