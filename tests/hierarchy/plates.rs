//! Parallel plates: the receiver's mean factor is the closed form `F = 0.19982` whatever
//! the levels of its links, and every leaf's arriving light is the exact factor of that
//! leaf (Gauss integration of the point factor) within the oracle's tolerance.

use super::{hierarchy, options};
use crate::support::{corner_factor, mean_over};
use std::path::Path;
use ugo::directions::DirectionSet;
use ugo::material::MaterialModel;
use ugo::progress::Silent;
use ugo::scene::Scene;

const L: f64 = 1000.0;

/// Point factor from `(x, y)` on the receiver to the unit square 1 m below.
fn point_factor(x: f64, y: f64) -> f64 {
    let f = |a: f64, b: f64| a.signum() * b.signum() * corner_factor(a.abs(), b.abs(), 1.0);
    f(1.0 - x, 1.0 - y) - f(-x, 1.0 - y) - f(1.0 - x, -y) + f(-x, -y)
}

/// `(mean F over the receiver, worst |F_leaf − exact|)` with the receiver's reflectance `rho`.
fn receiver(rho: f64, tolerance: f64) -> (f64, f64, usize) {
    let mut scene = Scene::load(Path::new("cases/parallel-plates.toml")).unwrap();
    scene.materials[0].model = MaterialModel::Lambert { reflectance: rho, transmittance: 0.0 };
    let mut h = hierarchy(&scene, 1.0, DirectionSet::single(), options(tolerance, 0.05));
    let op = h.operator(&Silent);
    let mesh = h.leaf_mesh();
    let l0 = h.emission();
    let mut z = vec![0.0; l0.len()];
    op.arriving(&l0, &mut z);
    let (mut flux, mut area, mut worst, mut leaves) = (0.0, 0.0, 0.0f64, 0);
    for (p, &zl) in mesh.patches.iter().zip(&z).filter(|(p, _)| p.surface == 1) {
        flux += zl * p.area;
        area += p.area;
        let (lo, hi) = (
            p.polygon.vertices().iter().fold(p.centroid, |a, v| a.min(*v)),
            p.polygon.vertices().iter().fold(p.centroid, |a, v| a.max(*v)),
        );
        let exact = mean_over((lo.x, hi.x), (lo.y, hi.y), 2, point_factor);
        worst = worst.max((zl / L - exact).abs());
        leaves += 1;
    }
    (flux / area / L, worst, leaves)
}

#[test]
fn receiver_mean_factor_is_the_closed_form() {
    let exact = 0.1998249;
    let (black, _, n) = receiver(0.0, 1e-3);
    eprintln!("plates, black receiver: {n} leaves, mean F = {black:.7} (exact {exact})");
    assert_eq!(n, 1, "a black receiver needs no refinement");
    // one link, its factor by the hierarchy's quadrature (`η = 1`): 3.3e-4 measured
    assert!((black / exact - 1.0).abs() < 5e-4, "{black}");
    let (grey, worst, n) = receiver(0.5, 1e-3);
    eprintln!("plates, grey receiver: {n} leaves, mean F = {grey:.7}, worst leaf |F − exact| = {worst:.2e}");
    assert!(n > 16, "a reflecting receiver refines");
    assert!((grey / exact - 1.0).abs() < 1e-4, "{grey}");
    assert!(worst < 2e-3 / 0.5, "worst leaf factor error {worst}");
}
