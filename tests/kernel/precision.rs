//! `G` stored in single precision: half the bytes per non-zero, and solutions that
//! differ from double precision only by the rounding of `G`.

use crate::support::{furnace, solve};
use std::path::Path;
use ugo::kernel::Precision;
use ugo::model::Model;
use ugo::scene::Scene;

fn model(scene: &Scene, patch_size: f64, precision: Precision) -> Model {
    let mut scene = scene.clone();
    (scene.discretization.patch_size, scene.discretization.precision) = (patch_size, precision);
    Model::build(&scene, &ugo::progress::Silent).unwrap()
}

#[test]
fn single_precision_halves_the_matrix_and_changes_solutions_only_by_rounding() {
    let scene = Scene::load(Path::new("cases/cornell-box.toml")).unwrap();
    let (double, single) = (model(&scene, 0.1, Precision::Double), model(&scene, 0.1, Precision::Single));
    assert_eq!(single.kernel.g.precision(), Precision::Single);
    assert_eq!(single.kernel.g.nnz(), double.kernel.g.nnz());
    let per = |m: &Model| m.kernel.g.bytes() / m.kernel.g.nnz() as f64;
    assert!(per(&double) >= 16.0 && per(&single) < 8.5, "{} and {} bytes per non-zero", per(&double), per(&single));
    let (x, y) = (solve(&double), solve(&single));
    let worst = x.iter().zip(&y).map(|(a, b)| ((a - b) / a.abs().max(1e-3)).abs()).fold(0.0, f64::max);
    eprintln!("largest relative difference f32 against f64 (Cornell box, patch 0.1): {worst:.2e}");
    assert!(worst > 0.0 && worst < 1e-5, "{worst:.2e}");
}

#[test]
fn the_single_precision_furnace_is_still_five() {
    let scene = furnace(1.0, 0.8, 1.0, 0.25);
    let x = solve(&model(&scene, 0.25, Precision::Single));
    let worst = x.iter().map(|l| (l - 5.0).abs()).fold(0.0, f64::max);
    assert!(worst < 1e-5, "{worst:.2e}");
}
