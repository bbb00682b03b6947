//! Balancing started from the last operator's factors (`balance.rs`, `Hierarchy::operator`):
//! an operator built again on the same links starts where the last one ended, so it is
//! balanced at once, to the same operator within the balancing's tolerance.

use super::{box_with_block, hierarchy, options, relative_difference};
use ugo::directions::DirectionSet;
use ugo::kernel::BalanceReport;
use ugo::kernel::hierarchy::Operator;
use ugo::progress::Silent;

fn balance(g: &Operator) -> BalanceReport {
    g.balanced().expect("balanced")
}

#[test]
fn an_operator_built_again_balances_from_the_last_factors() {
    let mut h = hierarchy(&box_with_block(0.8), 0.5, DirectionSet::single(), options(3e-2, 0.05));
    let first = h.operator(&Silent);
    let cold = balance(&first);
    let again = h.operator(&Silent);
    let warm = balance(&again);
    let y: Vec<f64> = (0..first.dim()).map(|i| 1.0 + (i % 7) as f64).collect();
    let (mut a, mut b) = (vec![0.0; y.len()], vec![0.0; y.len()]);
    first.arriving(&y, &mut a);
    again.arriving(&y, &mut b);
    let difference = relative_difference(&a, &b);
    eprintln!("first build {cold:?}; again {warm:?}; max |Δ(Gx)|/max|Gx| = {difference:.1e}");
    assert!(cold.iterations >= 4 && warm.iterations <= 1, "{} sweeps, then {}", cold.iterations, warm.iterations);
    assert!(warm.residual < 1e-4 && difference < 1e-4, "{warm:?}, {difference}");
}
