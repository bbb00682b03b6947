//! Means and standard errors of Monte Carlo estimates from running sums.
//!
//! An estimate is the mean of `n` independent samples `X`; its standard error is
//! `s/√n` with the sample variance `s² = (Σ X² − (Σ X)²/n)/(n − 1)`.

/// Running sums of one estimated quantity.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Tally {
    /// `Σ X`.
    pub sum: f64,
    /// `Σ X²`.
    pub squares: f64,
}

impl Tally {
    /// Adds the sample `x`.
    #[inline]
    pub fn add(&mut self, x: f64) {
        self.sum += x;
        self.squares += x * x;
    }

    /// Mean and standard error of the mean of `n` samples (zeros included).
    pub fn mean_and_error(&self, n: u64) -> (f64, f64) {
        if n == 0 {
            return (0.0, 0.0);
        }
        let nf = n as f64;
        let mean = self.sum / nf;
        let variance = if n > 1 { ((self.squares - self.sum * mean) / (nf - 1.0)).max(0.0) } else { 0.0 };
        (mean, (variance / nf).sqrt())
    }

    /// The total `Σ X` and its standard error `√n · s`, for a sum of `n` samples.
    pub fn total_and_error(&self, n: u64) -> (f64, f64) {
        let (mean, error) = self.mean_and_error(n);
        (mean * n as f64, error * n as f64)
    }
}
