//! Reciprocity-and-closure balancing of the exchange areas `T_ij = A_i F_ij`.
//!
//! The quadrature gives two estimates of one exchange area, `A_i F_ij` (integrated over
//! `i`) and `A_j F_ji` (over `j`); their mean `T` is symmetric. Each patch also knows its
//! closure `c_i = A_i Σ_j F_ij` from a target-independent rule, which is exact (to round-off)
//! in a closed convex enclosure. A symmetric diagonal scaling `D T D` with row sums `c`
//! (symmetric Sinkhorn–Knopp; Knight, SIAM J. Matrix Anal. Appl. 29 (2008)) makes the
//! kernel exactly reciprocal and closed, hence exactly energy conserving, while moving
//! each entry by no more than the quadrature's own error (reported as `max_correction`).

/// How far balancing moved the exchange areas.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct BalanceReport {
    /// `max_i |D_i² − 1|`: the largest relative change of a patch's row.
    pub max_correction: f64,
    /// Largest relative row-sum mismatch left, `max_i |(D T D 1)_i / c_i − 1|`.
    pub residual: f64,
    pub iterations: usize,
}

/// Finds `D` with `D_i Σ_j T_ij D_j = c_i`. `rows[i]` lists `(j, T_ij)` for every
/// `j ≠ i` (both triangles of the symmetric matrix).
pub fn balance(rows: &[Vec<(u32, f64)>], targets: &[f64]) -> (Vec<f64>, BalanceReport) {
    let n = rows.len();
    let mut d = vec![1.0; n];
    let mut report = BalanceReport::default();
    let row_sum = |d: &[f64], i: usize| rows[i].iter().map(|&(j, t)| t * d[j as usize]).sum::<f64>();
    for iteration in 1..=200 {
        let mut worst: f64 = 0.0;
        for i in 0..n {
            let s = row_sum(&d, i);
            if s > 0.0 && targets[i] > 0.0 {
                worst = worst.max((d[i] * s / targets[i] - 1.0).abs());
                d[i] = (d[i] * targets[i] / s).sqrt();
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
