//! Dense LU in faer against nalgebra (`ugo bench --lu`): factor and solve of an `n × n`
//! matrix like `I − K`, timed, with each residual.

use std::time::Instant;

/// One size measured.
#[derive(Debug, Clone, Copy)]
pub struct DenseLu {
    /// Unknowns.
    pub n: usize,
    /// faer's factor and solve, s.
    pub faer_seconds: f64,
    /// The largest absolute residual of faer's solution.
    pub faer_residual: f64,
    /// nalgebra's factor and solve, s.
    pub nalgebra_seconds: f64,
    /// The largest absolute residual of nalgebra's solution.
    pub nalgebra_residual: f64,
}

impl DenseLu {
    /// Floating-point operations of the factorization, `2n³/3`.
    pub fn flops(&self) -> f64 {
        2.0 / 3.0 * (self.n as f64).powi(3)
    }
}

/// Times the dense LU (factor and solve) of an `n × n` matrix like `I − K` in faer and in
/// nalgebra, and measures both residuals.
pub fn dense_lu(n: usize) -> DenseLu {
    let entry = |i: usize, j: usize| {
        let h = ((i * 7919 + j * 104_729) % 1000) as f64 / 1000.0;
        if i == j { 1.0 } else { -0.8 * h / n as f64 }
    };
    let b: Vec<f64> = (0..n).map(|i| 1.0 + (i % 3) as f64).collect();
    let residual = |x: &[f64]| {
        (0..n).map(|i| (0..n).map(|j| entry(i, j) * x[j]).sum::<f64>() - b[i]).map(f64::abs).fold(0.0, f64::max)
    };
    let t = Instant::now();
    let a = faer::Mat::<f64>::from_fn(n, n, entry);
    let x = faer::linalg::solvers::Solve::solve(&a.partial_piv_lu(), faer::Col::<f64>::from_fn(n, |i| b[i]));
    let faer_seconds = t.elapsed().as_secs_f64();
    let faer_x: Vec<f64> = (0..n).map(|i| x[i]).collect();
    let t = Instant::now();
    let a = nalgebra::DMatrix::<f64>::from_fn(n, n, entry);
    let x = a.lu().solve(&nalgebra::DVector::from_column_slice(&b)).unwrap_or_else(|| nalgebra::DVector::zeros(n));
    let nalgebra_seconds = t.elapsed().as_secs_f64();
    DenseLu {
        n,
        faer_seconds,
        faer_residual: residual(&faer_x),
        nalgebra_seconds,
        nalgebra_residual: residual(x.as_slice()),
    }
}
