//! The readings' importance (`kernel::importance`, `docs/design.md` (3b.3b)) is the adjoint
//! of the solve: for a reading `R = vᵀ x` of the field `x = b + K x`, `R = Wᵀ b` with
//! `W = v + Kᵀ W`, whatever `b`; with and without direction cells, on a refined hierarchy.

use super::transpose::{dot, wavy};
use super::{box_with_block, hierarchy, options, solved, solver};
use ugo::directions::DirectionSet;
use ugo::kernel::importance;
use ugo::solve::Method;

#[test]
fn importance_is_the_adjoint_of_the_solve() {
    for directions in [DirectionSet::single(), DirectionSet::hemisphere(8)] {
        let k = directions.len();
        let mut h = hierarchy(&box_with_block(0.7), 0.5, directions, options(1e-2, 0.1));
        let (_, kernel) = solved(&mut h, Method::Gmres { restart: 30 });
        let n = kernel.g.rows();
        // a reading that sees a few unknowns, and a source everywhere but uneven
        let v: Vec<f64> = (0..n).map(|i| if i % 17 == 3 { 1.0 + (i % 5) as f64 } else { 0.0 }).collect();
        let b = wavy(n, 0.4);
        let x = solver(Method::Gmres { restart: 30 })(&kernel, &b, 1.0).expect("the solve converges");
        let w = importance(&kernel, &v);
        let (forward, adjoint) = (dot(&v, &x), dot(&w, &b));
        eprintln!("K = {k}: {n} unknowns, vᵀx = {forward:.9e}, Wᵀb = {adjoint:.9e}");
        assert!((forward - adjoint).abs() < 1e-3 * forward, "K = {k}: {forward} against {adjoint}");
        assert!(w.iter().zip(&v).all(|(w, v)| w >= v), "the importance includes the direct share");
    }
}
