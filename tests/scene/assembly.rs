//! `[discretization] kernel`, `root_size` and `link_tolerance`: the hierarchical kernel chosen
//! in a case file, its defaults, and its keys refused where they do not apply; without
//! `kernel`, the kernel chosen by the uniform one's facing pairs; the old spelling (`method`,
//! `tolerance`, `smallest`, `patch_size` for the roots) read as the new one with a note.

use super::{BASE, LAMP, assert_error, parse, rejected};
use std::path::Path;
use ugo::scene::{ChosenBySize, FINE_PATCH, Hierarchical, KernelKind, ROOTS, Scene, SizeReason, UNIFORM_PAIRS};

fn with(keys: &str) -> String {
    format!("{}{LAMP}", BASE.replace("patch_size = 0.1", &format!("patch_size = 0.1\n{keys}")))
}

/// The unit cube of `cases/furnace-box.toml` at `patch_size` `h`, with `keys` in place of
/// the case's own `kernel` (the uniform one, on which the white furnace is exact).
fn cube(h: f64, keys: &str) -> Scene {
    Scene::parse(Path::new("cases/furnace-box.toml"), cube_text(h, keys)).unwrap()
}

fn cube_text(h: f64, keys: &str) -> String {
    let text = std::fs::read_to_string("cases/furnace-box.toml").unwrap();
    let kept: Vec<_> = text.lines().filter(|line| !line.starts_with("kernel = ")).collect();
    assert_eq!(kept.len() + 1, text.lines().count(), "the case names its kernel once");
    kept.join("\n").replace("patch_size = 0.1", &format!("patch_size = {h}\n{keys}"))
}

/// Facing pairs of the cube's uniform kernel at `h`: each of its 15 pairs of faces pairs
/// every patch of one face with every patch of the other, `(1/h)²` patches a face.
fn cube_pairs(h: f64) -> f64 {
    15.0 * (1.0 / h).round().powi(4)
}

fn hierarchical(root_size: f64, link_tolerance: f64) -> KernelKind {
    KernelKind::Hierarchical(Hierarchical {
        root_size,
        link_tolerance,
        passes: ugo::scene::Hierarchical::DEFAULT_PASSES,
    })
}

#[test]
fn without_kernel_it_is_chosen_by_the_uniform_ones_facing_pairs() {
    // 15 · 25⁴ = 5.9e6 pairs: uniform, as asked
    let (h, small) = (0.04, cube(0.04, ""));
    let d = &small.discretization;
    assert!(cube_pairs(h) < UNIFORM_PAIRS);
    assert_eq!((d.kernel, d.patch_size), (KernelKind::Uniform, h));
    let pairs = d.chosen_by_size.unwrap().facing_pairs;
    assert!((pairs / cube_pairs(h) - 1.0).abs() < 1e-9, "{pairs} pairs");
    assert_eq!(cube(h, "kernel = \"auto\"").discretization, *d);

    // 15 · 50⁴ = 9.4e7 pairs: the hierarchy, leaves down to the size asked, roots ROOTS times it
    let (h, large) = (0.02, cube(0.02, ""));
    let d = &large.discretization;
    assert!(cube_pairs(h) > UNIFORM_PAIRS);
    assert_eq!(d.kernel, hierarchical(ROOTS * h, 1e-2));
    assert_eq!(d.patch_size, h);
    let Some(ChosenBySize { patch_size, facing_pairs, reason }) = d.chosen_by_size else { panic!("not chosen") };
    assert_eq!((patch_size, reason), (h, SizeReason::TooManyPairs));
    assert!((facing_pairs / cube_pairs(h) - 1.0).abs() < 1e-9, "{facing_pairs} pairs");
    assert!(d.chosen_by_size.unwrap().to_string().contains("--kernel uniform"));

    // a kernel given is kept, whatever the size
    let given = cube(h, "kernel = \"uniform\"").discretization;
    assert_eq!((given.kernel, given.patch_size, given.chosen_by_size), (KernelKind::Uniform, h, None));
}

#[test]
fn affordable_uniform_patches_coarse_against_corners_take_the_hierarchy_unless_there_are_mirrors() {
    let chosen = |scene: &Scene| {
        let d = &scene.discretization;
        (d.kernel, d.chosen_by_size.expect("chosen").reason)
    };
    // 15 · 20⁴ pairs at FINE_PATCH: uniform; at 0.1 m the hierarchy
    assert_eq!(FINE_PATCH, 0.05);
    assert_eq!(chosen(&cube(0.05, "")), (KernelKind::Uniform, SizeReason::FinePatches));
    assert_eq!(chosen(&cube(0.1, "")), (hierarchical(ROOTS * 0.1, 1e-2), SizeReason::CoarsePatches));
    // 15 · 4⁴ = 3,840 pairs, well affordable, but patches of 0.25 m: the hierarchy
    let coarse = cube(0.25, "");
    assert!(cube_pairs(0.25) < UNIFORM_PAIRS);
    assert_eq!(chosen(&coarse), (hierarchical(ROOTS * 0.25, 1e-2), SizeReason::CoarsePatches));
    let told = coarse.discretization.chosen_by_size.unwrap().to_string();
    assert!(told.contains("over 0.05 m") && told.contains("--kernel uniform"), "{told}");
    // the same cube with mirror walls keeps the uniform kernel, the one that carries images
    let text = cube_text(0.25, "");
    let mirrors = text.replace("type = \"lambert\"", "type = \"mirror\"");
    assert_ne!(mirrors, text);
    let mirrored = Scene::parse(Path::new("cases/furnace-box.toml"), mirrors).unwrap();
    assert_eq!(chosen(&mirrored), (KernelKind::Uniform, SizeReason::Mirrors));
    // --patch-size chooses again: the mirrorless cube at 0.05 m is uniform
    let mut again = coarse;
    let finer =
        ugo::scene::Asked { patch_size: Some(ugo::scene::Given::flag("--patch-size")(0.05)), ..Default::default() };
    again.discretize(&finer).unwrap();
    assert_eq!(chosen(&again), (KernelKind::Uniform, SizeReason::FinePatches));
}

#[test]
fn the_hierarchical_kernel_takes_its_defaults_and_its_keys() {
    let scene = parse(&with("kernel = \"hierarchical\"")).unwrap();
    assert_eq!(scene.discretization.kernel, hierarchical(0.4, 1e-2), "roots 4 times the patch size");
    assert_eq!(scene.discretization.patch_size, 0.1);
    let scene = parse(&with("kernel = \"hierarchical\"\nlink_tolerance = 3e-3\nroot_size = 0.5")).unwrap();
    assert_eq!(scene.discretization.kernel, hierarchical(0.5, 3e-3));
    assert!(scene.old_spelling.is_empty());
}

#[test]
fn its_keys_are_refused_with_the_uniform_kernel_or_out_of_range() {
    let refused = |keys: &str, key: &str, fragments: &[&str]| {
        assert_error(&rejected(&with(keys)), "[discretization]", key, fragments);
    };
    refused("link_tolerance = 1e-2", "link_tolerance", &["hierarchical"]);
    refused("kernel = \"uniform\"\nroot_size = 1", "root_size", &["hierarchical"]);
    refused("kernel = \"hierarchical\"\nroot_size = 0.05", "root_size", &["smaller than patch_size"]);
    refused("kernel = \"hierarchical\"\nlink_tolerance = -1", "link_tolerance", &["greater than 0"]);
    refused("kernel = \"hierarchical\"\nlink_tolerance = 1", "link_tolerance", &["below 1"]);
    refused("kernel = \"radiosity\"", "kernel", &["hierarchical", "auto"]);
    // the old keys with the new spelling, and the two spellings of one key
    refused("kernel = \"hierarchical\"\nsmallest = 0.05", "smallest", &["patch_size"]);
    refused("kernel = \"hierarchical\"\ntolerance = 0.05", "tolerance", &["link_tolerance"]);
    refused("kernel = \"uniform\"\nmethod = \"explicit\"", "method", &["kernel"]);
}

#[test]
fn the_old_spelling_is_read_as_the_new_one_with_a_note() {
    // `patch_size` was the roots, `smallest` (default 0.05 m) the finest leaves
    let scene = parse(&with("method = \"hierarchical\"\ntolerance = 3e-3\nsmallest = 0.02")).unwrap();
    assert_eq!(scene.discretization.kernel, hierarchical(0.1, 3e-3));
    assert_eq!(scene.discretization.patch_size, 0.02);
    let notes: Vec<String> = scene.old_spelling.iter().map(|n| n.to_string()).collect();
    assert!(notes.iter().any(|n| n.contains("`root_size = 0.1`")), "{notes:?}");
    assert!(notes.iter().any(|n| n.contains("`link_tolerance = 0.003`")), "{notes:?}");
    let scene = parse(&with("method = \"hierarchical\"")).unwrap();
    assert_eq!((scene.discretization.kernel, scene.discretization.patch_size), (hierarchical(0.1, 1e-2), 0.05));
    let scene = parse(&with("method = \"explicit\"")).unwrap();
    assert_eq!((scene.discretization.kernel, scene.discretization.patch_size), (KernelKind::Uniform, 0.1));
    assert_eq!(scene.old_spelling.len(), 1);
    // its own rules stand, naming its own keys
    let refused = |keys: &str, key: &str, fragments: &[&str]| {
        assert_error(&rejected(&with(keys)), "[discretization]", key, fragments);
    };
    refused("method = \"hierarchical\"\nsmallest = 0.5", "smallest", &["exceeds patch_size"]);
    refused("method = \"hierarchical\"\ntolerance = -1", "tolerance", &[]);
    refused("method = \"auto\"\nsmallest = 0.05", "smallest", &["hierarchical"]);
    refused("method = \"radiosity\"", "method", &["hierarchical", "auto"]);
}
