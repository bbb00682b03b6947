//! The reflection-order record (`docs/design.md` §4): the norms of the order terms `K^n L0`
//! and the partial sums `Σ_{m≤n} K^m L0` after chosen orders (the lecture's pictures after
//! 1, 8 and 64 reflections).

use super::LinOp;
use super::outcome::norm;

/// Norms of every order term and the partial sums after the requested orders.
#[derive(Debug, Clone, PartialEq)]
pub struct OrderRecord {
    /// `‖K^n L0‖₂` for `n = 0..=max(orders)`.
    pub term_norms: Vec<f64>,
    /// `(n, Σ_{m≤n} K^m L0)` for each requested `n`, ascending.
    pub partial_sums: Vec<(usize, Vec<f64>)>,
}

/// Applies `K` up to the largest requested order.
pub fn reflection_orders(kernel: &dyn LinOp, l0: &[f64], orders: &[usize]) -> OrderRecord {
    let mut wanted: Vec<usize> = orders.to_vec();
    wanted.sort_unstable();
    wanted.dedup();
    let last = wanted.last().copied().unwrap_or(0);
    let mut term = l0.to_vec();
    let mut next = vec![0.0; l0.len()];
    let mut sum = l0.to_vec();
    let mut record = OrderRecord { term_norms: vec![norm(&term)], partial_sums: Vec::new() };
    for n in 0..=last {
        if n > 0 {
            kernel.apply(&term, &mut next);
            std::mem::swap(&mut term, &mut next);
            sum.iter_mut().zip(&term).for_each(|(s, t)| *s += t);
            record.term_norms.push(norm(&term));
        }
        if wanted.contains(&n) {
            record.partial_sums.push((n, sum.clone()));
        }
    }
    record
}
