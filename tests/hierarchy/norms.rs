//! The norms of the hierarchical kernel without its explicit product (`Norms::matrix_free`):
//! `‖K‖∞ = max K·1`, `‖K‖₁ = max Kᵀ·1` and `cond∞(I − K)` equal those of the explicit
//! expansion of the same hierarchy (`Norms::of`) to round-off, and `ρ(K)` by Arnoldi equals
//! power iteration's on the expansion to Arnoldi's tolerance, on a box with a glossy block
//! (`B ≠ Bᵀ`) and a two-sided transmitting panel (`Bᵀ` through the twins); a closed grey
//! furnace has `‖K‖∞ = ρ` to its closure error; a negative block keeps the refusal.

use super::{box_with_block, hierarchy, kernel, options};
use crate::support::{furnace, surface};
use glam::DVec3;
use ugo::directions::DirectionSet;
use ugo::geometry::{Emission, Shape, Surface};
use ugo::kernel::{Explicit, Factored, Kernel, TooLarge};
use ugo::material::{Block, MaterialModel};
use ugo::scene::{Material, Scene};
use ugo::solve::norms::{Estimator, Norms};
use ugo::solve::{ArnoldiParams, arnoldi};

/// The box with a Phong block and a two-sided panel that transmits 0.3 and reflects 0.4.
fn glossy_box_with_panel() -> Scene {
    let mut s = box_with_block(0.6);
    s.materials[1].model = MaterialModel::Phong { diffuse: 0.3, specular: 0.4, exponent: 8.0 };
    s.materials.push(Material {
        name: "panel".into(),
        model: MaterialModel::Lambert { reflectance: 0.4, transmittance: 0.3 },
    });
    let shape = Shape::Rectangle {
        origin: DVec3::new(0.1, 0.7, 0.1),
        edge_u: DVec3::new(0.5, 0.0, 0.0),
        edge_v: DVec3::new(0.0, 0.1, 0.5),
    };
    s.surfaces.push(Surface { two_sided: true, ..surface("panel", shape, 2, false, None::<Emission>) });
    s
}

/// The refusal of `k`'s explicit product under a limit of 0 bytes.
fn refused(k: &Kernel) -> TooLarge {
    k.explicit(0).expect_err("nothing fits in 0 bytes")
}

/// The matrix-free norms of `k` (Arnoldi for two eigenvalues) and those of its expansion.
fn both(k: &Kernel) -> (Norms, Norms) {
    let op = Factored::new(k);
    let spectrum = arnoldi(&op, &ArnoldiParams::largest(2)).unwrap();
    let free = Norms::matrix_free(&op, &spectrum, refused(k)).expect("K ≥ 0");
    let product = k.explicit(u64::MAX).unwrap();
    assert!(product.data().iter().all(|&v| v >= 0.0), "the expansion has a negative entry");
    (free, Norms::of(&Explicit(product)))
}

fn relative(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

#[test]
fn matrix_free_norms_equal_those_of_the_expansion() {
    for directions in [DirectionSet::single(), DirectionSet::hemisphere(8)] {
        let cells = directions.len();
        let mut h = hierarchy(&glossy_box_with_panel(), 0.5, directions, options(1e-2, 0.25));
        let k = kernel(&mut h);
        assert!(k.twin.iter().any(|&t| t != ugo::geometry::NO_TWIN), "the panel has twins");
        let (free, explicit) = both(&k);
        eprintln!("K = {cells}, {} unknowns: matrix-free {free:?}\n  explicit {explicit:?}", k.g.rows());
        assert!(relative(free.infinity, explicit.infinity) < 1e-12, "‖K‖∞");
        assert!(relative(free.one, explicit.one) < 1e-12, "‖K‖₁");
        assert!(free.one != free.infinity, "K is not symmetric: the two norms differ");
        let (r, e) = (free.spectral_radius, explicit.spectral_radius);
        assert!(r.converged && e.converged && r.by == Estimator::Arnoldi);
        // The power iteration stops at a change of 1e-12 per iteration, which bounds its
        // error only by that over 1 − |λ₂/λ₁|: since narrow surfaces are not graded the
        // two agree to 1.4e-11 at K = 1 with leaves of 0.25 m (to 1.2e-8 with leaves of 0.15 m).
        assert!(relative(r.value, e.value) < 1e-7, "ρ(K): Arnoldi {} against power {}", r.value, e.value);
        assert!(relative(free.condition_infinity, explicit.condition_infinity) < 1e-9, "cond∞(I − K)");
        assert!(free.frobenius.is_none() && free.two.is_none() && free.matrix_free.is_some());
        let two = explicit.two.unwrap().value;
        assert!(r.value <= two + 1e-9 && two <= free.two_bound() + 1e-12, "ρ ≤ ‖K‖₂ ≤ √(‖K‖₁‖K‖∞)");
    }
}

#[test]
fn matrix_free_infinity_norm_of_a_closed_furnace_is_its_reflectance() {
    let rho = 0.8;
    let mut h = hierarchy(&furnace(1.0, rho, 1.0, 1.0), 1.0, DirectionSet::single(), options(1e-2, 0.1));
    let k = kernel(&mut h);
    let (free, _) = both(&k);
    eprintln!("hierarchical furnace: ‖K‖∞ {} ‖K‖₁ {} ρ(K) {}", free.infinity, free.one, free.spectral_radius.value);
    // the balanced hierarchy closes every row: K·1 = ρ·1 to the closure's error
    assert!(relative(free.infinity, rho) < 1e-3, "‖K‖∞ = {}", free.infinity);
    assert!(relative(free.spectral_radius.value, rho) < 1e-3);
    assert!(free.spectral_radius.value <= free.infinity.min(free.one) + 1e-12);
}

#[test]
fn a_negative_block_keeps_the_refusal() {
    let mut h = hierarchy(&furnace(1.0, 0.8, 1.0, 1.0), 1.0, DirectionSet::single(), options(1e-2, 0.25));
    let mut k = kernel(&mut h);
    k.blocks[0] = Block::new(1, vec![-0.1], None);
    let op = Factored::new(&k);
    let spectrum = arnoldi(&op, &ArnoldiParams::largest(2)).unwrap();
    let refusal = refused(&k);
    assert_eq!(Norms::matrix_free(&op, &spectrum, refusal.clone()), Err(refusal));
}
