//! The white furnace `L = L0/(1 − ρ)` and the divergence of a lossless closed scene.

use crate::support::{build, furnace};
use ugo::kernel::Factored;
use ugo::readout::energy::EnergyBalance;
use ugo::solve::{SolveError, SolveParams, successive_approximation};

fn params() -> SolveParams {
    SolveParams { tolerance: 1e-10, max_iterations: 10_000, ..SolveParams::default() }
}

#[test]
fn furnace_box_is_five_everywhere_and_conserves_energy() {
    let scene = furnace(1.0, 0.8, 1.0, 0.1);
    let model = build(&scene);
    assert!(model.mesh.len() >= 600);
    let (x, info) =
        successive_approximation(&Factored::new(&model.kernel), &model.l0, &params(), &mut |_, _| {}).unwrap();
    let worst = x.iter().map(|l| (l / 5.0 - 1.0).abs()).fold(0.0, f64::max);
    eprintln!(
        "furnace: {} patches, {} iterations, worst relative error {worst:.2e}",
        model.mesh.len(),
        info.iterations
    );
    assert!(worst < 1e-3, "worst relative error {worst}");
    assert!(info.residual() <= 1e-10);
    let e = EnergyBalance::of(&model, &x, 1);
    assert!((e.absorbed / e.emitted - 1.0).abs() < 1e-6, "{e:?}");
    assert!(e.escaped.abs() < 1e-6 * e.emitted);
}

#[test]
fn lossless_closed_box_is_reported_divergent() {
    let scene = furnace(1.0, 1.0, 1.0, 0.25);
    let model = build(&scene);
    let err =
        successive_approximation(&Factored::new(&model.kernel), &model.l0, &params(), &mut |_, _| {}).unwrap_err();
    assert!(matches!(err, SolveError::Diverges { .. }), "{err}");
    assert!(err.to_string().contains("spectral radius"));
}
