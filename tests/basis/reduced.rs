//! SH and SVD solutions of the reduced system against the full angular solution: exact
//! for a Lambertian scene at the lowest order, converging on a glossy box, exact once the
//! basis spans the cells, and the same answer from every solver of the laboratory.

use crate::support::{build_with, lambert, material, rectangle, scene, surface};
use glam::DVec3;
use ugo::basis::{Basis, BasisError, Factorization, Reduced};
use ugo::directions::DirectionSet;
use ugo::geometry::{Emission, Shape};
use ugo::kernel::{Explicit, Factored};
use ugo::material::MaterialModel;
use ugo::model::Model;
use ugo::solve::{Method, SolveParams, System, solve};

fn tight() -> SolveParams {
    SolveParams { tolerance: 1e-12, max_iterations: 5000, ..SolveParams::default() }
}

/// A closed unit room of `walls` lit by a black 0.4 m square lamp under the ceiling.
fn room(walls: MaterialModel, cells: usize) -> Model {
    let shape = Shape::Box { min: DVec3::ZERO, max: DVec3::ONE, rotate_y_deg: 0.0 };
    let lamp = rectangle([0.3, 0.99, 0.3], [0.4, 0.0, 0.0], [0.0, 0.0, 0.4]);
    let s = scene(
        vec![material("walls", walls), lambert("black", 0.0)],
        vec![surface("room", shape, 0, true, None), surface("lamp", lamp, 1, false, Some(Emission::Luminance(100.0)))],
        0.25,
    );
    build_with(&s, DirectionSet::hemisphere(cells))
}

fn full(model: &Model) -> Vec<f64> {
    let factored = Factored::new(&model.kernel);
    let system = System::of(&model.kernel, &factored, None, &[], &model.l0);
    solve(Method::Gmres { restart: 50 }, &system, &tight(), &mut |_, _| {}).unwrap().0
}

/// The reduced solution in `basis` by `method`, as a full field.
fn reduced(model: &Model, basis: Basis, method: Method) -> Vec<f64> {
    let factors = Factorization::new(basis, &model.kernel.blocks, &model.kernel.directions).unwrap();
    let op = Reduced::new(&model.kernel, &factors);
    let source = op.source(&model.l0);
    let explicit = method.needs_explicit().then(|| Explicit(op.explicit(u64::MAX).unwrap()));
    let system = System { operator: &op, explicit: explicit.as_ref(), areas: &[], l0: &source };
    let c = solve(method, &system, &tight(), &mut |_, _| {}).unwrap().0;
    op.field(&model.l0, &c)
}

fn relative(a: &[f64], b: &[f64]) -> f64 {
    let d: f64 = a.iter().zip(b).map(|(x, y)| (x - y).powi(2)).sum();
    (d / b.iter().map(|y| y * y).sum::<f64>()).sqrt()
}

#[test]
fn a_lambertian_scene_is_exact_at_the_lowest_order() {
    let model = room(MaterialModel::Lambert { reflectance: 0.7, transmittance: 0.0 }, 16);
    let reference = full(&model);
    for basis in [Basis::Sh { lmax: 0 }, Basis::Svd { rank: 1 }] {
        let e = relative(&reduced(&model, basis, Method::Gmres { restart: 50 }), &reference);
        assert!(e < 1e-10, "{}: {e:.2e}", basis.name());
    }
}

#[test]
fn glossy_solutions_converge_to_the_full_angular_one_and_svd_is_exact_at_full_rank() {
    let model = room(MaterialModel::Phong { diffuse: 0.2, specular: 0.6, exponent: 8.0 }, 64);
    let reference = full(&model);
    let gmres = Method::Gmres { restart: 50 };
    let sh: Vec<f64> =
        [1, 2, 3, 5, 7].iter().map(|&l| relative(&reduced(&model, Basis::Sh { lmax: l }, gmres), &reference)).collect();
    let svd: Vec<f64> =
        [4, 9, 16, 36].iter().map(|&r| relative(&reduced(&model, Basis::Svd { rank: r }, gmres), &reference)).collect();
    eprintln!("relative L² error, sh l = 1, 2, 3, 5, 7: {sh:?}; svd R = 4, 9, 16, 36: {svd:?}");
    for errors in [&sh, &svd] {
        assert!(errors.windows(2).all(|p| p[1] < p[0]), "errors do not decrease: {errors:?}");
        assert!(errors[3] < 1e-2, "not within 1 % at l = 5 / R = 36: {errors:?}");
    }
    // The SVD of full rank is the block itself; the 64 harmonics of l = 7 are not
    // independent on the 64 cells (the polar cap and the small rings alias high azimuthal
    // orders), so SH stops short of exactness.
    let e = relative(&reduced(&model, Basis::Svd { rank: 64 }, gmres), &reference);
    assert!(e < 1e-9, "svd:64 spans the 64 cells: {e:.2e}");
    let sh7 = Factorization::new(Basis::Sh { lmax: 7 }, &model.kernel.blocks, &model.kernel.directions).unwrap();
    assert!(sh7.rank < 64, "rank {}", sh7.rank);
}

#[test]
fn every_solver_solves_the_reduced_system() {
    let model = room(MaterialModel::Phong { diffuse: 0.3, specular: 0.5, exponent: 8.0 }, 16);
    let basis = Basis::Sh { lmax: 2 };
    let reference = reduced(&model, basis, Method::Direct);
    for method in [Method::Neumann, Method::GaussSeidel, Method::Gmres { restart: 30 }, Method::Bicgstab] {
        let e = relative(&reduced(&model, basis, method), &reference);
        assert!(e < 1e-8, "{}: {e:.2e}", method.name());
    }
}

#[test]
fn a_basis_larger_than_the_cells_is_refused() {
    let model = room(MaterialModel::Phong { diffuse: 0.3, specular: 0.5, exponent: 8.0 }, 16);
    let err = Factorization::new(Basis::Sh { lmax: 4 }, &model.kernel.blocks, &model.kernel.directions).unwrap_err();
    assert!(matches!(err, BasisError::TooLarge { m: 25, k: 16, .. }), "{err}");
    assert!(Basis::parse("sh:3") == Some(Basis::Sh { lmax: 3 }) && Basis::parse("svd:0").is_none());
}
