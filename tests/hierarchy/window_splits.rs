//! The hierarchy splits its leaves along the openings' light (issue 39, point 2): in the
//! daylit office (a 3 × 1.5 m window, overcast sky, no other light) every leaf that could
//! still be split holds the sky's light, read exactly at points the oracle does not use,
//! within 1.5 times the oracle's allowance. Before, windows split nothing (0 splits, and a
//! 1 m floor root in the far corner spanned 78.4 lx where 1.5 times the allowance is 53 lx).
//! And the sun patch's edge is drawn within one smallest leaf of its exact line.

use std::f64::consts::PI;
use std::path::Path;
use ugo::luminaire::{Light, arriving_along};
use ugo::model::Model;
use ugo::progress::Silent;
use ugo::scene::{Hierarchical, KernelKind, Scene};

/// Smallest leaves, m: roots of 1 m split at most twice.
const SMALLEST: f64 = 0.25;

#[test]
fn the_window_light_splits_the_leaves_until_it_is_even_on_each() {
    let mut scene = Scene::load(Path::new("cases/daylit-office.toml")).unwrap();
    let kernel =
        Hierarchical { root_size: 1.0, link_tolerance: 1e-1, passes: ugo::scene::Hierarchical::DEFAULT_PASSES };
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
                    ugo::sky::READING,
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

/// The daylit office lit by a 50,000 lx sun through its window alone (the sky off, no
/// glass): where the sun patch's exact edges (the window's edges cast along the beam onto
/// the floor) cross a floor leaf, that leaf is of the smallest size, so the patch's edge
/// is drawn within one smallest element of its exact line.
#[test]
fn the_sun_patch_edge_lies_within_one_smallest_leaf_of_its_exact_line() {
    let path = Path::new("cases/daylit-office.toml");
    let text = std::fs::read_to_string(path).unwrap();
    let text =
        text.replace("horizontal_illuminance = 10000.0", "horizontal_illuminance = 1e-9\nsun_illuminance = 50000.0");
    let mut scene = Scene::parse(path, text).unwrap();
    scene.discretization.kernel = KernelKind::Hierarchical(Hierarchical {
        root_size: 1.0,
        link_tolerance: 1e-1,
        passes: ugo::scene::Hierarchical::DEFAULT_PASSES,
    });
    scene.discretization.patch_size = SMALLEST;
    let model = Model::build(&scene, &Silent).expect("fits in memory");
    let beam = model.sources.iter().find_map(|s| match &s.light {
        Light::Parallel { direction, .. } => Some(*direction),
        _ => None,
    });
    let beam = beam.expect("the sun shines");
    let window = scene.luminaires.iter().find_map(|l| match &l.kind {
        ugo::luminaire::LuminaireKind::Window { window, .. } => Some(window.polygon),
        _ => None,
    });
    // The window's corners cast along the beam onto the floor (y = 0), in (x, z).
    let cast: Vec<(f64, f64)> = window
        .expect("a window")
        .vertices()
        .iter()
        .map(|v| {
            let t = -v.y / beam.y;
            (v.x + t * beam.x, v.z + t * beam.z)
        })
        .collect();
    let crosses = |leaf: &[(f64, f64)], a: (f64, f64), b: (f64, f64)| {
        let (dx, dz) = (b.0 - a.0, b.1 - a.1);
        let length = (dx * dx + dz * dz).sqrt();
        let side = |p: &(f64, f64)| (dx * (p.1 - a.1) - dz * (p.0 - a.0)) / length;
        let along = |p: &(f64, f64)| (dx * (p.0 - a.0) + dz * (p.1 - a.1)) / length;
        let both = leaf.iter().any(|p| side(p) > 1e-9) && leaf.iter().any(|p| side(p) < -1e-9);
        let (lo, hi) =
            leaf.iter().map(along).fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), s| (l.min(s), h.max(s)));
        both && hi > 1e-9 && lo < length - 1e-9
    };
    let (mut crossed, mut coarse) = (0, Vec::new());
    for leaf in model.mesh.patches.iter().filter(|p| p.normal.y > 0.99 && p.centroid.y.abs() < 1e-9) {
        let corners: Vec<(f64, f64)> = leaf.polygon.vertices().iter().map(|v| (v.x, v.z)).collect();
        if (0..cast.len()).any(|i| crosses(&corners, cast[i], cast[(i + 1) % cast.len()])) {
            crossed += 1;
            let longest = leaf.polygon.vertices().windows(2).map(|e| (e[1] - e[0]).length()).fold(0.0, f64::max);
            if longest > SMALLEST * (1.0 + 1e-9) {
                coarse.push((leaf.centroid, longest));
            }
        }
    }
    eprintln!("{crossed} floor leaves on the sun patch's edges, {} larger than {SMALLEST} m", coarse.len());
    assert!(crossed >= 8, "only {crossed} floor leaves on the sun patch's edges");
    assert!(coarse.is_empty(), "leaves on the sun patch's edge larger than the smallest: {coarse:?}");
}
