//! Absurd magnitudes (issue 18, item 2): values that would overflow the field are refused
//! at the key that holds them, never left to a solver to report as divergence; values
//! that are valid but rarely meant are warnings naming the table and the key.

use super::{BASE, LAMP, assert_error, lit, parse, rejected};
use crate::support::scratch;

const LAMP_TABLE: &str = "[[surface]] \"lamp\" (#1)";

fn lamp_with(emission: &str) -> String {
    lit("").replace("{ luminance = 100.0 }", emission)
}

#[test]
fn emission_that_would_overflow_is_refused_at_its_key() {
    for (emission, key) in [
        ("{ luminance = 1e308 }", "emission.luminance"),
        ("{ luminance = 1e21 }", "emission.luminance"),
        ("{ flux = 1e300 }", "emission.flux"),
    ] {
        assert_error(&rejected(&lamp_with(emission)), LAMP_TABLE, key, &["out of range", "at most 1e20"]);
    }
    // A plausible flux on a microscopic disc is an absurd luminance.
    let tiny = lamp_with("{ flux = 1e10 }").replace("radius = 0.2", "radius = 1e-12");
    assert_error(&rejected(&tiny), LAMP_TABLE, "emission.flux", &["out of range", "cd/m²"]);
    assert_error(&rejected(&lamp_with("{ luminance = nan }")), LAMP_TABLE, "emission.luminance", &["finite"]);
}

fn luminaire(keys: &str) -> String {
    format!("{BASE}{LAMP}\n[[luminaire]]\nname = \"l\"\n{keys}\n")
}

const L: &str = "[[luminaire]] \"l\" (#1)";

#[test]
fn luminaire_magnitudes_that_would_overflow_are_refused_at_their_key() {
    let iso = "type = \"isotropic\"\nposition = [0, 1, 0]\n";
    assert_error(&rejected(&luminaire(&format!("{iso}flux = 1e30"))), L, "flux", &["out of range"]);
    assert_error(&rejected(&luminaire(&format!("{iso}intensity = 1e300"))), L, "intensity", &["out of range"]);
    assert_error(
        &rejected(&luminaire(&format!("{iso}flux = 1\nmultiplier = 1e25"))),
        L,
        "multiplier",
        &["out of range"],
    );
    let sun = "type = \"parallel\"\ndirection = [0, -1, 0]\nilluminance = 1e300";
    assert_error(&rejected(&luminaire(sun)), L, "illuminance", &["out of range"]);
    let dir = scratch("ies-overflow");
    dir.write("lamp.ies", &std::fs::read_to_string("tests/data/photometry/c-axial-lambert-2002.ies").unwrap());
    let text = luminaire("type = \"ies\"\nposition = [0, 1, 0]\nfile = \"lamp.ies\"\nmultiplier = 1e19");
    let case = dir.write("case.toml", &text);
    let error = ugo::scene::Scene::parse(&case, text).expect_err("accepted");
    assert_eq!((error.table(), error.key()), (L, "file"), "{error}");
    assert!(error.message().contains("out of range"), "{error}");
}

/// The warnings of a valid scene, as `(table, key)`.
fn warned(text: &str) -> Vec<(String, String, String)> {
    let scene = parse(text).unwrap_or_else(|e| panic!("{e}"));
    scene.warnings().iter().map(|w| (w.table().to_string(), w.key().to_string(), w.message().to_string())).collect()
}

#[test]
fn implausible_values_are_warnings_naming_table_and_key() {
    assert!(warned(&lit("")).is_empty());
    let w = warned(&lamp_with("{ luminance = 1e10 }"));
    assert_eq!((w[0].0.as_str(), w[0].1.as_str()), (LAMP_TABLE, "emission.luminance"), "{w:?}");
    assert!(w[0].2.contains("brighter than the sun"), "{w:?}");
    let w = warned(&lamp_with("{ flux = 1e8 }"));
    assert_eq!(w[0].1, "emission.flux", "{w:?}");
    let w = warned(&lit("").replace("reflectance = 0.75", "reflectance = 0.99"));
    assert_eq!((w[0].0.as_str(), w[0].1.as_str()), ("[[material]] \"white\" (#1)", "reflectance"), "{w:?}");
    let w = warned(&lit("").replace("radius = 0.2", "radius = 1e-5"));
    assert_eq!((w[0].1.as_str(), w[0].2.contains("metres")), ("radius", true), "{w:?}");
    let room = "\n[[surface]]\nname = \"hall\"\nshape = \"box\"\nmaterial = \"white\"\nmin = [0, 0, 0]\nmax = [5000, 3000, 4000]\n";
    let w = warned(&lit(room));
    assert_eq!((w[0].0.as_str(), w[0].1.as_str()), ("[[surface]] \"hall\" (#2)", "shape"), "{w:?}");
    let sun = "\n[[luminaire]]\nname = \"sun\"\ntype = \"parallel\"\ndirection = [0, -1, 0]\nilluminance = 2e5\n";
    let w = warned(&lit(sun));
    assert_eq!(w[0].1, "illuminance", "{w:?}");
}

#[test]
fn a_model_in_millimetres_is_told_the_scale_that_fixes_it() {
    let dir = scratch("obj-mm");
    dir.write("chair.obj", "v 0 0 0\nv 900 0 0\nv 0 900 450\nf 1 2 3\n");
    let text = lit("\n[[surface]]\nname = \"chair\"\nshape = \"mesh\"\nmaterial = \"white\"\nfile = \"chair.obj\"\n");
    let case = dir.write("case.toml", &text);
    let scene = ugo::scene::Scene::parse(&case, text).unwrap();
    let w = scene.warnings();
    assert_eq!(w.len(), 1, "{w:?}");
    assert_eq!((w[0].table(), w[0].key()), ("[[surface]] \"chair\" (#2)", "scale"));
    assert!(w[0].message().contains("scale = 0.001"), "{}", w[0]);
}

/// Below 500 units a model in millimetres is no longer than a hall; beside a room it is
/// still tens of times the room (issue 37, point 7).
#[test]
fn a_millimetre_model_far_larger_than_its_room_is_told_the_scale() {
    let dir = scratch("obj-mm-small");
    dir.write("stool.obj", "v 0 0 0\nv 300 0 0\nv 0 300 200\nf 1 2 3\n");
    let room = "\n[[surface]]\nname = \"room\"\nshape = \"box\"\nmaterial = \"white\"\nmin = [-2, 0, -2]\nmax = [2, 3, 2]\ninside = true\n";
    let stool = "\n[[surface]]\nname = \"stool\"\nshape = \"mesh\"\nmaterial = \"white\"\nfile = \"stool.obj\"\n";
    let text = lit(&format!("{room}{stool}"));
    let case = dir.write("case.toml", &text);
    let w = ugo::scene::Scene::parse(&case, text).unwrap().warnings();
    assert_eq!(w.len(), 1, "{w:?}");
    assert_eq!((w[0].table(), w[0].key()), ("[[surface]] \"stool\" (#3)", "scale"));
    assert!(
        w[0].message().contains("times the rest of the scene") && w[0].message().contains("scale = 0.001"),
        "{}",
        w[0]
    );
    // the same stool in metres is no mistake
    let metres = dir.write("metres.toml", &lit(&format!("{room}{stool}scale = 0.001\n")));
    let w = ugo::scene::Scene::load(&metres).unwrap().warnings();
    assert!(w.is_empty(), "{w:?}");
}
