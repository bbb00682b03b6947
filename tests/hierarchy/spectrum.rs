//! ugo's Arnoldi on the hierarchical operator (matrix-free, no explicit matrix): a closed
//! grey furnace has `λ₁ = ρ` to its closure error and the same `λ₁` as power iteration.

use super::{hierarchy, kernel, options};
use crate::support::furnace;
use ugo::directions::DirectionSet;
use ugo::kernel::Factored;
use ugo::solve::{ArnoldiParams, arnoldi};

#[test]
fn arnoldi_runs_on_the_hierarchical_operator() {
    let mut h = hierarchy(&furnace(1.0, 0.8, 1.0, 1.0), 1.0, DirectionSet::single(), options(1e-2, 0.1));
    let k = kernel(&mut h);
    let op = Factored::new(&k);
    let spectrum = arnoldi(&op, &ArnoldiParams::largest(4)).unwrap();
    assert!(spectrum.converged);
    let lambda = spectrum.pairs[0].re;
    // Power iteration on the same operator.
    let mut v = vec![1.0; op.dim()];
    let mut w = vec![0.0; op.dim()];
    let mut power = 0.0;
    for _ in 0..400 {
        op.apply(&v, &mut w);
        power = w.iter().map(|x| x * x).sum::<f64>().sqrt() / v.iter().map(|x| x * x).sum::<f64>().sqrt();
        v.copy_from_slice(&w);
        let length = v.iter().map(|x| x * x).sum::<f64>().sqrt();
        v.iter_mut().for_each(|x| *x /= length);
    }
    eprintln!("hierarchical furnace: {} leaves, λ₁ = {lambda:.12}, power {power:.12}", op.dim());
    assert!((lambda - power).abs() < 1e-9, "{lambda} against {power}");
    assert!((lambda - 0.8).abs() < 1e-3 * 0.8, "λ₁ = {lambda}");
    assert!(
        spectrum.pairs.iter().all(|p| p.residual < 1e-9),
        "{:?}",
        spectrum.pairs.iter().map(|p| p.residual).collect::<Vec<_>>()
    );
    assert!(spectrum.pairs[0].vector_re.iter().all(|&x| x > 0.0));
}
