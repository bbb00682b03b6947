//! Reciprocity-and-closure balancing of the exchange areas `T[(i,d),(j,m)] = A_i F_ij^{d,m}`.
//!
//! The quadrature gives two estimates of one exchange area (integrated over `i` and over
//! `j`); their mean `T` is symmetric. Each row also has a target: the closure it must
//! carry. A symmetric diagonal scaling `D T D` with those row sums (symmetric
//! Sinkhorn–Knopp in Gauss–Seidel sweeps, `D_r ← target_r / Σ_c T_rc D_c`, rows of `T`
//! having no diagonal; Knight, SIAM J. Matrix Anal. Appl. 29 (2008)) makes the kernel exactly reciprocal and closed, hence exactly energy
//! conserving, while moving each entry only as far as the targets demand (reported as
//! `max_correction`).

use crate::kernel::BalanceReport;
use sprs::CsMat;

/// Finds `D` with `D_r Σ_c T_rc D_c = target_r` for the symmetric matrix `t`; rows with a
/// zero sum or target keep `D_r = 1`.
pub fn balance(t: &CsMat<f64>, targets: &[f64]) -> (Vec<f64>, BalanceReport) {
    let n = t.rows();
    let mut d = vec![1.0; n];
    let mut report = BalanceReport::default();
    let (indptr, indices, data) = (t.indptr(), t.indices(), t.data());
    let indptr = indptr.raw_storage();
    for iteration in 1..=MAX_SWEEPS {
        let mut worst: f64 = 0.0;
        for r in 0..n {
            let (lo, hi) = (indptr[r], indptr[r + 1]);
            let s: f64 = indices[lo..hi].iter().zip(&data[lo..hi]).map(|(&c, &v)| v * d[c]).sum();
            if s > 0.0 && targets[r] > 0.0 {
                worst = worst.max((d[r] * s / targets[r] - 1.0).abs());
                d[r] = targets[r] / s;
            }
        }
        report.iterations = iteration;
        report.residual = worst;
        if worst < 1e-14 {
            break;
        }
    }
    report.max_correction = d.iter().map(|x| (x * x - 1.0).abs()).fold(0.0, f64::max);
    (d, report)
}

/// Sweeps before balancing gives up (it reports the residual it reached).
const MAX_SWEEPS: usize = 1000;
