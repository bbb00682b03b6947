//! `[discretization] method`, `tolerance` and `smallest`: the hierarchical kernel chosen in
//! a case file, its defaults, and its keys refused where they do not apply; without
//! `method`, the kernel chosen by the explicit one's facing pairs.

use super::{BASE, LAMP, assert_error, parse, rejected};
use std::path::Path;
use ugo::scene::{Assembly, Automatic, EXPLICIT_PAIRS, ROOTS, Scene};

fn with(keys: &str) -> String {
    format!("{}{LAMP}", BASE.replace("patch_size = 0.1", &format!("patch_size = 0.1\n{keys}")))
}

/// The unit cube of `cases/furnace-box.toml` at `patch_size` `h`, with `keys` after it.
fn cube(h: f64, keys: &str) -> Scene {
    let text = std::fs::read_to_string("cases/furnace-box.toml").unwrap();
    let text = text.replace("patch_size = 0.1", &format!("patch_size = {h}\n{keys}"));
    Scene::parse(Path::new("cases/furnace-box.toml"), text).unwrap()
}

/// Facing pairs of the cube's explicit kernel at `h`: each of its 15 pairs of faces pairs
/// every patch of one face with every patch of the other, `(1/h)²` patches a face.
fn cube_pairs(h: f64) -> f64 {
    15.0 * (1.0 / h).round().powi(4)
}

#[test]
fn without_method_the_kernel_is_chosen_by_the_explicit_ones_facing_pairs() {
    // 15 · 25⁴ = 5.9e6 pairs: explicit, as asked
    let (h, small) = (0.04, cube(0.04, ""));
    let d = &small.discretization;
    assert!(cube_pairs(h) < EXPLICIT_PAIRS);
    assert_eq!((d.assembly, d.patch_size), (Assembly::Explicit, h));
    let pairs = d.automatic.unwrap().facing_pairs;
    assert!((pairs / cube_pairs(h) - 1.0).abs() < 1e-9, "{pairs} pairs");
    assert_eq!(cube(h, "method = \"auto\"").discretization, *d);

    // 15 · 50⁴ = 9.4e7 pairs: the hierarchy, split down to the size asked from roots ROOTS times it
    let (h, large) = (0.02, cube(0.02, ""));
    let d = &large.discretization;
    assert!(cube_pairs(h) > EXPLICIT_PAIRS);
    let tolerance = ugo::kernel::hierarchy::Options::default().tolerance;
    assert_eq!(d.assembly, Assembly::Hierarchical { tolerance, smallest: h });
    assert!((d.patch_size - ROOTS * h).abs() < 1e-12);
    let Some(Automatic { asked, facing_pairs }) = d.automatic else { panic!("not chosen") };
    assert_eq!(asked, h);
    assert!((facing_pairs / cube_pairs(h) - 1.0).abs() < 1e-9, "{facing_pairs} pairs");
    assert!(d.automatic.unwrap().to_string().contains("--assembly explicit"));

    // a method given is kept, whatever the size
    let given = cube(h, "method = \"explicit\"").discretization;
    assert_eq!((given.assembly, given.patch_size, given.automatic), (Assembly::Explicit, h, None));
}

#[test]
fn the_hierarchical_kernel_takes_its_defaults_and_its_keys() {
    let scene = parse(&with("method = \"hierarchical\"")).unwrap();
    assert_eq!(scene.discretization.assembly, Assembly::hierarchical());
    let scene = parse(&with("method = \"hierarchical\"\ntolerance = 3e-3\nsmallest = 0.02")).unwrap();
    assert_eq!(scene.discretization.assembly, Assembly::Hierarchical { tolerance: 3e-3, smallest: 0.02 });
}

#[test]
fn its_keys_are_refused_with_the_explicit_kernel_or_out_of_range() {
    assert_error(&rejected(&with("tolerance = 1e-2")), "[discretization]", "tolerance", &["hierarchical"]);
    assert_error(
        &rejected(&with("method = \"hierarchical\"\nsmallest = 0.5")),
        "[discretization]",
        "smallest",
        &["exceeds patch_size"],
    );
    assert_error(&rejected(&with("method = \"hierarchical\"\ntolerance = -1")), "[discretization]", "tolerance", &[]);
    assert_error(
        &rejected(&with("method = \"auto\"\nsmallest = 0.05")),
        "[discretization]",
        "smallest",
        &["hierarchical"],
    );
    assert_error(&rejected(&with("method = \"radiosity\"")), "[discretization]", "method", &["hierarchical", "auto"]);
}
