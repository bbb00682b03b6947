//! Closure and the white furnace: `K·1 = ρ` on every leaf of a closed box, and
//! `L = L0/(1 − ρ)` with every solver.

use super::{hierarchy, kernel, links, options, solved, solver};
use crate::support::furnace;
use ugo::directions::DirectionSet;
use ugo::kernel::Factored;
use ugo::solve::Method;

#[test]
fn a_closed_box_closes_on_every_leaf() {
    let mut h = hierarchy(&furnace(1.0, 1.0, 1.0, 1.0), 1.0, DirectionSet::single(), options(0.1, 0.1));
    let k = kernel(&mut h);
    let ones = vec![1.0; k.g.rows()];
    let mut y = vec![0.0; k.g.rows()];
    Factored::new(&k).apply(&ones, &mut y);
    let worst = y.iter().map(|v| (v - 1.0).abs()).fold(0.0, f64::max);
    eprintln!("closure: {} leaves, {} links, worst |K·1 − 1| = {worst:.2e}", k.g.rows(), links(&k));
    assert!(worst < 1e-3, "worst closure error {worst}");
}

#[test]
fn white_furnace_is_five_on_every_leaf_with_every_solver() {
    let mut h = hierarchy(&furnace(1.0, 0.8, 1.0, 1.0), 1.0, DirectionSet::single(), options(1e-2, 0.1));
    let (x, op) = solved(&mut h, Method::Gmres { restart: 30 });
    let l0 = h.emission();
    for (method, x) in [
        (Method::Gmres { restart: 30 }, x),
        (Method::Neumann, solver(Method::Neumann)(&op, &l0, 1.0).unwrap()),
        (Method::Bicgstab, solver(Method::Bicgstab)(&op, &l0, 1.0).unwrap()),
    ] {
        let worst = x.iter().map(|l| (l / 5.0 - 1.0).abs()).fold(0.0, f64::max);
        eprintln!(
            "furnace, {}: {} leaves, {} links, worst relative error {worst:.2e}",
            method.name(),
            op.g.rows(),
            links(&op)
        );
        assert!(worst < 1e-3, "{}: worst relative error {worst}", method.name());
    }
}

#[test]
fn white_furnace_with_direction_cells_is_five_in_every_cell() {
    let directions = DirectionSet::hemisphere(8);
    let mut h = hierarchy(&furnace(1.0, 0.8, 1.0, 1.0), 1.0, directions, options(1e-2, 0.1));
    let (x, op) = solved(&mut h, Method::Gmres { restart: 30 });
    let worst = x.iter().map(|l| (l / 5.0 - 1.0).abs()).fold(0.0, f64::max);
    eprintln!("furnace, K = 8: {} unknowns, {} links, worst relative error {worst:.2e}", op.g.rows(), links(&op));
    assert_eq!(op.g.rows(), 8 * h.leaf_mesh().len());
    assert!(worst < 1e-3, "worst relative error {worst}");
}
