//! Successive right-hand sides against one kernel (`solve::Projection`): every solve meets
//! the cold solve's stopping rule and agrees with it, a source in the span of the known
//! solutions' sources starts within round-off of its solution, and one that is not starts
//! cold, at no extra cost.

use crate::support::{build, furnace};
use ugo::kernel::Factored;
use ugo::solve::{LinOp, Method, Projection, SolveParams, System};

/// Three sources on the patches of a grey furnace: a ramp, a comb and a single patch.
fn sources(n: usize) -> [Vec<f64>; 3] {
    [
        (0..n).map(|i| i as f64 / n as f64).collect(),
        (0..n).map(|i| if i % 3 == 0 { 2.0 } else { 0.0 }).collect(),
        (0..n).map(|i| if i == n / 2 { 50.0 } else { 0.0 }).collect(),
    ]
}

/// `‖b − (I − K) x‖ / ‖b‖`.
fn residual(op: &dyn LinOp, b: &[f64], x: &[f64]) -> f64 {
    let mut kx = vec![0.0; x.len()];
    op.apply(x, &mut kx);
    let r: f64 = b.iter().zip(x).zip(&kx).map(|((b, x), k)| (b - x + k).powi(2)).sum();
    (r / b.iter().map(|b| b * b).sum::<f64>()).sqrt()
}

fn largest_difference(a: &[f64], b: &[f64]) -> f64 {
    let scale = b.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    a.iter().zip(b).fold(0.0f64, |m, (a, b)| m.max((a - b).abs())) / scale
}

#[test]
fn warm_solves_agree_with_cold_ones_and_the_last_of_a_known_sum_is_almost_free() {
    let model = build(&furnace(1.0, 0.8, 1.0, 0.2));
    let op = Factored::new(&model.kernel);
    let b = sources(op.dim());
    let sum: Vec<f64> = (0..op.dim()).map(|i| b[0][i] + b[1][i] + b[2][i]).collect();
    let params = SolveParams { tolerance: 1e-10, ..SolveParams::default() };
    let method = Method::Gmres { restart: 30 };
    let system = |l0| System { operator: &op, explicit: None, areas: &[], l0 };
    let mut cold = Projection::new(false);
    let mut warm = Projection::new(true);
    let all = cold.solve(method, &system(&sum), &params, &mut |_, _| {}).unwrap();
    warm.learn(&op, all.x.clone());
    for (j, b) in b.iter().enumerate() {
        let c = cold.solve(method, &system(b), &params, &mut |_, _| {}).unwrap();
        let w = warm.solve(method, &system(b), &params, &mut |_, _| {}).unwrap();
        assert_eq!(c.start, 1.0);
        for s in [&c, &w] {
            assert!(s.residual <= 1e-10 && (residual(&op, b, &s.x) - s.residual).abs() < 1e-13, "source {j}");
        }
        assert!(largest_difference(&w.x, &c.x) < 1e-9, "source {j}: {}", largest_difference(&w.x, &c.x));
        if j < 2 {
            assert_eq!((w.start, w.applications), (1.0, c.applications), "source {j}: not in the known span, cold");
        } else {
            assert!(w.start < 1e-8, "the last source is the known sum less the others: starts at {}", w.start);
            assert!(w.applications * 2 < c.applications, "{} against {}", w.applications, c.applications);
        }
    }
}

#[test]
fn a_known_solution_learnt_twice_or_a_zero_source_does_no_harm() {
    let model = build(&furnace(1.0, 0.5, 1.0, 0.25));
    let op = Factored::new(&model.kernel);
    let params = SolveParams { tolerance: 1e-10, ..SolveParams::default() };
    let system = |l0| System { operator: &op, explicit: None, areas: &[], l0 };
    let mut warm = Projection::new(true);
    let first = warm.solve(Method::Bicgstab, &system(&model.l0), &params, &mut |_, _| {}).unwrap();
    warm.learn(&op, first.x.clone());
    let again = warm.solve(Method::Neumann, &system(&model.l0), &params, &mut |_, _| {}).unwrap();
    assert!(again.start <= 1e-10 && again.info.iterations == 0, "starts at {}", again.start);
    assert!(largest_difference(&again.x, &first.x) < 1e-9);
    let zero = vec![0.0; op.dim()];
    let none = warm.solve(Method::Gmres { restart: 30 }, &system(&zero), &params, &mut |_, _| {}).unwrap();
    assert!(none.x.iter().all(|&x| x == 0.0) && none.residual == 0.0);
}
