//! `[discretization] method`, `tolerance` and `smallest`: the hierarchical kernel chosen in
//! a case file, its defaults, and its keys refused where they do not apply.

use super::{BASE, LAMP, assert_error, parse, rejected};
use ugo::scene::Assembly;

fn with(keys: &str) -> String {
    format!("{}{LAMP}", BASE.replace("patch_size = 0.1", &format!("patch_size = 0.1\n{keys}")))
}

#[test]
fn the_explicit_kernel_is_the_default() {
    let scene = parse(&with("")).unwrap();
    assert_eq!(scene.discretization.assembly, Assembly::Explicit);
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
    assert_error(&rejected(&with("method = \"radiosity\"")), "[discretization]", "method", &["hierarchical"]);
}
