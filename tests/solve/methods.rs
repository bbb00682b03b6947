//! Every method of the laboratory on the same system, against the direct solution.

use crate::support::{build_with, furnace, furnace_of};
use ugo::directions::DirectionSet;
use ugo::kernel::{Explicit, Factored};
use ugo::material::MaterialModel;
use ugo::model::Model;
use ugo::solve::norms::Norms;
use ugo::solve::orders::reflection_orders;
use ugo::solve::{Algorithm, Method, SolveError, SolveParams, System, solve};

fn tight() -> SolveParams {
    SolveParams { tolerance: 1e-12, max_iterations: 5000, ..SolveParams::default() }
}

fn run(model: &Model, explicit: &Explicit, method: Method) -> Result<Vec<f64>, SolveError> {
    let areas: Vec<f64> = model.mesh.patches.iter().map(|p| p.area).collect();
    let factored = Factored::new(&model.kernel);
    let system = System::of(&model.kernel, &factored, Some(explicit), &areas, &model.l0);
    solve(method, &system, &tight(), &mut |_, _| {}).map(|r| r.0)
}

fn relative_difference(a: &[f64], b: &[f64]) -> f64 {
    let d: f64 = a.iter().zip(b).map(|(x, y)| (x - y) * (x - y)).sum::<f64>().sqrt();
    d / b.iter().map(|y| y * y).sum::<f64>().sqrt()
}

/// A glossy box with a diffuse emitting floor: phong walls, K = 16.
fn glossy_model() -> Model {
    let mut scene = furnace_of(MaterialModel::Phong { diffuse: 0.3, specular: 0.5, exponent: 20.0 }, 1.0, 0.34);
    scene.surfaces[0].emission = Some(ugo::geometry::Emission::Luminance(1.0));
    build_with(&scene, DirectionSet::hemisphere(16))
}

#[test]
fn every_method_agrees_with_the_direct_solution_on_a_glossy_scene() {
    let model = glossy_model();
    let explicit = Explicit(model.kernel.explicit(u64::MAX).unwrap());
    let reference = run(&model, &explicit, Method::Direct).unwrap();
    for method in [Method::Neumann, Method::GaussSeidel, Method::Gmres { restart: 30 }, Method::Bicgstab] {
        let x = run(&model, &explicit, method).unwrap();
        let d = relative_difference(&x, &reference);
        eprintln!("{}: {d:.2e} from direct", method.name());
        assert!(d < 1e-8, "{} differs from direct by {d}", method.name());
    }
}

#[test]
fn southwell_agrees_with_the_direct_solution_for_radiosity() {
    let model = build_with(&furnace(1.0, 0.7, 1.0, 0.25), DirectionSet::single());
    let explicit = Explicit(model.kernel.explicit(u64::MAX).unwrap());
    let reference = run(&model, &explicit, Method::Direct).unwrap();
    let x = run(&model, &explicit, Method::Southwell).unwrap();
    assert!(relative_difference(&x, &reference) < 1e-8);
}

#[test]
fn southwell_refuses_direction_cells() {
    let model = glossy_model();
    let explicit = Explicit(model.kernel.explicit(u64::MAX).unwrap());
    assert!(matches!(run(&model, &explicit, Method::Southwell), Err(SolveError::Unsupported { .. })));
}

#[test]
fn spectral_radius_of_a_closed_box_is_its_reflectance() {
    for rho in [0.3, 0.8, 0.95] {
        let model = build_with(&furnace(1.0, rho, 1.0, 0.25), DirectionSet::single());
        let norms = Norms::of(&Explicit(model.kernel.explicit(u64::MAX).unwrap()));
        // The balanced kernel closes every row exactly, so ρ(K) = ρ up to round-off; the raw
        // quadrature's closure error (1e-6 here) is the looser bound the issue asks for.
        assert!(norms.spectral_radius.converged);
        assert!((norms.spectral_radius.value / rho - 1.0).abs() < 1e-6, "{:?}", norms.spectral_radius);
        assert!((norms.infinity - rho).abs() < 1e-9);
        // cond∞(I − K) = (1 + ρ)/(1 − ρ) for a constant row sum ρ
        assert!(
            (norms.condition_infinity / ((1.0 + rho) / (1.0 - rho)) - 1.0).abs() < 1e-6,
            "{}",
            norms.condition_infinity
        );
        assert!(norms.two.unwrap().value >= norms.spectral_radius.value - 1e-9);
    }
}

#[test]
fn reflection_orders_leave_the_furnace_deficit_rho_to_the_n_plus_one() {
    let rho = 0.8;
    let model = build_with(&furnace(1.0, rho, 1.0, 0.25), DirectionSet::single());
    let record = reflection_orders(&Factored::new(&model.kernel), &model.l0, &[1, 8, 64]);
    assert_eq!(record.term_norms.len(), 65);
    for (n, sum) in &record.partial_sums {
        let exact = (1.0 - rho.powi(*n as i32 + 1)) / (1.0 - rho);
        assert!(sum.iter().all(|l| (l / exact - 1.0).abs() < 1e-9), "order {n}");
    }
    let ratio = record.term_norms[10] / record.term_norms[9];
    assert!((ratio - rho).abs() < 1e-9);
}

#[test]
fn a_singular_system_is_reported_not_looped() {
    let model = build_with(&furnace(1.0, 1.0, 1.0, 0.34), DirectionSet::single());
    let explicit = Explicit(model.kernel.explicit(u64::MAX).unwrap());
    let err = run(&model, &explicit, Method::Gmres { restart: 5 }).unwrap_err();
    assert!(
        matches!(err, SolveError::Stagnation { .. } | SolveError::NoConvergence { .. } | SolveError::Singular { .. }),
        "{err}"
    );
}

#[test]
fn a_direct_solve_over_the_limit_is_refused_with_the_estimate() {
    let model = glossy_model();
    let explicit = Explicit(model.kernel.explicit(u64::MAX).unwrap());
    let areas: Vec<f64> = model.mesh.patches.iter().map(|p| p.area).collect();
    let factored = Factored::new(&model.kernel);
    let system = System::of(&model.kernel, &factored, Some(&explicit), &areas, &model.l0);
    let err =
        solve(Method::Direct, &system, &SolveParams { memory_limit: 1 << 20, ..tight() }, &mut |_, _| {}).unwrap_err();
    assert!(matches!(err, SolveError::TooLarge(_)) && err.to_string().contains("GMRES"), "{err}");
}

#[test]
fn sparse_and_dense_lu_agree() {
    let model = glossy_model();
    let explicit = Explicit(model.kernel.explicit(u64::MAX).unwrap());
    let (dense, _) = ugo::solve::direct(&explicit, &model.l0, &tight(), &mut |_, _| {}).unwrap();
    let (sparse, info) = ugo::solve::direct_sparse(&explicit, &model.l0, &tight(), &mut |_, _| {}).unwrap();
    assert_eq!(info.method, Algorithm::SparseLu);
    assert_eq!(info.method.to_string(), "direct (sparse LU)");
    assert!(relative_difference(&sparse, &dense) < 1e-12);
    assert!(info.residual() < 1e-13);
}
