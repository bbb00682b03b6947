//! ugo's own Arnoldi (`solve/arnoldi.rs`) against a dense eigen-decomposition (nalgebra,
//! independent of the faer one inside), against power iteration's `ρ(K)` (`solve/norms.rs`),
//! its eigen-residuals, and the Perron vector of a closed grey furnace box.

use crate::support::{build, furnace};
use nalgebra::DMatrix;
use std::path::Path;
use ugo::kernel::{Explicit, Factored};
use ugo::model::Model;
use ugo::random::Rng;
use ugo::scene::Scene;
use ugo::solve::norms::Norms;
use ugo::solve::{ArnoldiError, ArnoldiParams, LinOp, Spectrum, arnoldi};

/// A dense matrix as an operator.
struct Dense(DMatrix<f64>);

impl LinOp for Dense {
    fn dim(&self) -> usize {
        self.0.nrows()
    }

    fn apply(&self, x: &[f64], y: &mut [f64]) {
        let v = &self.0 * nalgebra::DVector::from_column_slice(x);
        y.copy_from_slice(v.as_slice());
    }
}

/// The eigenvalues of `a`, largest magnitude first (conjugates: positive imaginary part first).
fn dense_eigenvalues(a: &DMatrix<f64>) -> Vec<(f64, f64)> {
    let mut values: Vec<(f64, f64)> = a.complex_eigenvalues().iter().map(|c| (c.re, c.im)).collect();
    values
        .sort_by(|a, b| b.0.hypot(b.1).total_cmp(&a.0.hypot(a.1)).then(b.0.total_cmp(&a.0)).then(b.1.total_cmp(&a.1)));
    values
}

/// Every computed eigenvalue equals the dense one of the same rank to `tolerance · |λ₁|`.
fn assert_matches(spectrum: &Spectrum, dense: &[(f64, f64)], tolerance: f64) {
    let scale = dense[0].0.hypot(dense[0].1);
    for (j, (pair, &(re, im))) in spectrum.pairs.iter().zip(dense).enumerate() {
        let error = (pair.re - re).hypot(pair.im - im) / scale;
        eprintln!(
            "  λ{} = {:+.12} {:+.12}i, dense {re:+.12} {im:+.12}i, error {error:.1e}, residual {:.1e}",
            j + 1,
            pair.re,
            pair.im,
            pair.residual
        );
        assert!(error < tolerance, "λ{}: {error:.2e}", j + 1);
        assert!(pair.residual < tolerance * scale, "residual of λ{}: {:.2e}", j + 1, pair.residual);
    }
}

fn cornell(patch_size: f64) -> Model {
    let scene = Scene::load(Path::new("cases/cornell-box.toml")).unwrap();
    let mut scene = scene;
    scene.discretization.patch_size = patch_size;
    Model::build(&scene, &ugo::progress::Silent).unwrap()
}

#[test]
fn arnoldi_finds_the_complex_eigenvalues_of_a_random_matrix() {
    let n = 120;
    let mut rng = Rng::stream(7, 0);
    let a = DMatrix::<f64>::from_fn(n, n, |_, _| rng.uniform() - 0.5);
    let spectrum = arnoldi(&Dense(a.clone()), &ArnoldiParams::largest(8)).unwrap();
    let dense = dense_eigenvalues(&a);
    assert!(dense[..8].iter().any(|v| v.1 != 0.0), "the test wants complex eigenvalues");
    eprintln!("random {n}×{n}: {} restarts, {} products", spectrum.restarts, spectrum.applications);
    assert!(spectrum.converged);
    assert_matches(&spectrum, &dense, 1e-8);
}

#[test]
fn arnoldi_matches_the_dense_spectrum_of_the_cornell_kernel_and_power_iteration() {
    let model = cornell(0.12);
    let explicit = Explicit(model.kernel.explicit(1 << 30).unwrap());
    let n = explicit.dim();
    let mut a = DMatrix::<f64>::zeros(n, n);
    for (i, row) in explicit.0.outer_iterator().enumerate() {
        for (j, v) in row.iter() {
            a[(i, j)] = *v;
        }
    }
    let spectrum = arnoldi(&Factored::new(&model.kernel), &ArnoldiParams::largest(6)).unwrap();
    eprintln!("Cornell box, {n} unknowns: {} restarts, {} products", spectrum.restarts, spectrum.applications);
    assert!(spectrum.converged);
    assert_matches(&spectrum, &dense_eigenvalues(&a), 1e-8);
    let power = Norms::of(&explicit).spectral_radius;
    assert!(power.converged);
    let rho = spectrum.pairs[0].magnitude();
    eprintln!("ρ(K): Arnoldi {rho:.12}, power iteration {:.12}", power.value);
    assert!((rho - power.value).abs() < 1e-8 * power.value);
}

#[test]
fn the_perron_vector_of_a_closed_grey_furnace_is_constant() {
    let reflectance = 0.8;
    let model = build(&furnace(1.0, reflectance, 1.0, 0.2));
    let spectrum = arnoldi(&Factored::new(&model.kernel), &ArnoldiParams::largest(3)).unwrap();
    let perron = &spectrum.pairs[0];
    assert!((perron.re - reflectance).abs() < 1e-8 && perron.im == 0.0, "λ₁ = {} + {}i", perron.re, perron.im);
    let worst = perron.vector_re.iter().map(|v| (v - 1.0).abs()).fold(0.0, f64::max);
    eprintln!(
        "furnace: λ₁ = {:.12}, |λ₂| = {:.6}, Perron vector within {worst:.1e} of 1",
        perron.re,
        spectrum.pairs[1].magnitude()
    );
    assert!(worst < 1e-6, "{worst:.2e}");
    assert!(perron.vector_im.iter().all(|&v| v == 0.0));
}

#[test]
fn a_spectrum_larger_than_the_operator_is_refused() {
    let a = Dense(DMatrix::<f64>::identity(3, 3));
    let err = arnoldi(&a, &ArnoldiParams::largest(4)).unwrap_err();
    assert_eq!(err, ArnoldiError::Count { count: 4, dim: 3 });
    assert!(err.to_string().contains("1 to 3"));
    assert!(arnoldi(&a, &ArnoldiParams::largest(0)).is_err());
}

#[test]
fn an_invariant_start_and_a_repeated_eigenvalue_are_handled() {
    // The identity: every start vector spans an invariant subspace at once.
    let n = 40;
    let spectrum = arnoldi(&Dense(DMatrix::<f64>::identity(n, n) * 0.5), &ArnoldiParams::largest(3)).unwrap();
    assert!(spectrum.converged);
    for pair in &spectrum.pairs {
        assert!((pair.re - 0.5).abs() < 1e-12 && pair.residual < 1e-12, "{pair:?}");
    }
}
