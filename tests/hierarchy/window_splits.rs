//! The hierarchy splits its leaves along the openings' light (issue 39, point 2): in the
//! daylit office (a 3 × 1.5 m window, overcast sky, no other light) every leaf that could
//! still be split holds the sky's light, read exactly at points the oracle does not use,
//! within 1.5 times the oracle's allowance. Before, windows split nothing (0 splits, and a
//! 1 m floor root in the far corner spanned 78.4 lx where 1.5 times the allowance is 53 lx).

use std::f64::consts::PI;
use std::path::Path;
use ugo::luminaire::arriving_along;
use ugo::model::Model;
use ugo::progress::Silent;
use ugo::scene::{Hierarchical, KernelKind, Scene};

/// Smallest leaves, m: roots of 1 m split at most twice.
const SMALLEST: f64 = 0.25;

#[test]
fn the_window_light_splits_the_leaves_until_it_is_even_on_each() {
    let mut scene = Scene::load(Path::new("cases/daylit-office.toml")).unwrap();
    let kernel = Hierarchical { root_size: 1.0, link_tolerance: 1e-1 };
    scene.discretization.kernel = KernelKind::Hierarchical(kernel);
    scene.discretization.patch_size = SMALLEST;
    let model = Model::build(&scene, &Silent).expect("fits in memory");
    let record = model.hierarchy.as_ref().expect("hierarchical");
    let splits: usize = record.history.iter().map(|p| p.source_splits).sum();
    assert!(splits > 0, "the window's light split no leaf");
    let epsilon = record.history.iter().map(|p| p.epsilon).fold(f64::INFINITY, f64::min);
    // The case's reflectances, by material.
    let albedo = |m: u32| match scene.materials[m as usize].name.as_str() {
        "ceiling" => 0.7,
        "wall" => 0.5,
        "floor" => 0.2,
        other => panic!("material {other} not in the daylit office"),
    };
    let mut checked = 0;
    for leaf in &model.mesh.patches {
        let allowed = 1.5 * epsilon * PI / albedo(leaf.material);
        let longest = leaf.polygon.vertices().windows(2).map(|e| (e[1] - e[0]).length()).fold(0.0, f64::max);
        if longest <= SMALLEST * (1.0 + 1e-9) {
            continue;
        }
        // The exact light (every piece of the window cut for size, `sky::ETA`) at five
        // points that are not the oracle's.
        let points = leaf.polygon.vertices().iter().map(|v| v.lerp(leaf.centroid, 0.1)).chain([leaf.centroid]);
        let e: Vec<f64> = points
            .map(|x| {
                let mut e = 0.0;
                arriving_along(
                    &model.sources,
                    &model.visibility,
                    x,
                    leaf.normal,
                    leaf.face,
                    ugo::sky::ETA,
                    &mut |_, d| e += d * PI,
                );
                e
            })
            .collect();
        let spread = e.iter().fold(0.0f64, |m, &x| m.max(x)) - e.iter().fold(f64::INFINITY, |m, &x| m.min(x));
        assert!(
            spread <= allowed,
            "floor leaf at {}: the sky's light spans {spread:.1} lx (allowed {allowed:.1})",
            leaf.centroid
        );
        checked += 1;
    }
    assert!(checked >= 4, "only {checked} leaves above the smallest size to check");
}
