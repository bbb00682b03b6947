//! `Gᵀ` of the hierarchy (`Operator::leaving`) is the transpose of its `G`
//! (`Operator::arriving`): `⟨y, G x⟩ = ⟨Gᵀ y, x⟩` for any `x`, `y`, with and without
//! direction cells, on a refined hierarchy with element and cluster links.

use super::{box_with_block, hierarchy, options, solved};
use ugo::directions::DirectionSet;
use ugo::solve::Method;

/// `n` values between 0.3 and 1.7 along a sine of `phase`.
pub(super) fn wavy(n: usize, phase: f64) -> Vec<f64> {
    (0..n).map(|i| 1.0 + 0.7 * (i as f64 * 0.37 + phase).sin()).collect()
}

/// `aᵀb`.
pub(super) fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(a, b)| a * b).sum()
}

#[test]
fn leaving_is_the_transpose_of_arriving() {
    for directions in [DirectionSet::single(), DirectionSet::hemisphere(8)] {
        let k = directions.len();
        let mut h = hierarchy(&box_with_block(0.6), 0.5, directions, options(1e-2, 0.1));
        let (_, kernel) = solved(&mut h, Method::Gmres { restart: 30 });
        let Some(op) = kernel.g.hierarchy() else { panic!("not hierarchical") };
        let (x, y) = (wavy(op.dim(), 0.0), wavy(op.dim(), 1.3));
        let (mut gx, mut gty) = (vec![0.0; op.dim()], vec![0.0; op.dim()]);
        op.arriving(&x, &mut gx);
        op.leaving(&y, &mut gty);
        let (a, b) = (dot(&y, &gx), dot(&gty, &x));
        eprintln!("K = {k}: {} unknowns, {} links, ⟨y, Gx⟩ = {a:.12e}, ⟨Gᵀy, x⟩ = {b:.12e}", op.dim(), op.links());
        assert!(a > 0.0 && (a - b).abs() < 1e-12 * a, "K = {k}: {a} against {b}");
    }
}

/// `Gᵀ y`'s scatters split between one, three and four tasks (as many as the threads of the pool
/// the operator is built in, `transpose.rs`) add up to the same `Gᵀ y`, to rounding.
#[test]
fn leaving_is_the_same_on_one_three_and_four_threads() {
    let directions = DirectionSet::hemisphere(8);
    let on = |threads: usize| {
        let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
        pool.install(|| {
            let mut h = hierarchy(&box_with_block(0.6), 0.5, directions.clone(), options(1e-2, 0.1));
            let (_, kernel) = solved(&mut h, Method::Gmres { restart: 30 });
            let Some(op) = kernel.g.hierarchy() else { panic!("not hierarchical") };
            let mut gty = vec![0.0; op.dim()];
            op.leaving(&wavy(op.dim(), 1.3), &mut gty);
            gty
        })
    };
    let one = on(1);
    for threads in [3, 4] {
        let many = on(threads);
        let largest = one.iter().map(|v| v.abs()).fold(0.0, f64::max);
        let worst = one.iter().zip(&many).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max);
        eprintln!("{threads} threads: largest difference {worst:.3e} of {largest:.3e}");
        assert!(one.len() == many.len() && worst <= 1e-12 * largest, "{threads} threads: {worst} of {largest}");
    }
}
