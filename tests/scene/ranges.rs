//! Ranges before meshing (issue 18, item 3): coordinates and lengths the generator found
//! aborting or hanging in meshing, and direction counts past the 16-bit cell indices, are
//! refused at their key with the range exceeded.

use super::{BASE, assert_error, lit, parse, rejected};

fn surface(shape: &str, keys: &str) -> String {
    lit(&format!("\n[[surface]]\nname = \"s\"\nshape = \"{shape}\"\nmaterial = \"white\"\n{keys}\n"))
}

const S: &str = "[[surface]] \"s\" (#2)";

#[test]
fn coordinates_and_lengths_past_a_thousand_kilometres_are_refused_at_their_key() {
    for (shape, keys, key) in [
        ("polygon", "vertices = [[0, 0, 0], [1e150, 0, 0], [0, 0, 1e150]]", "vertices"),
        ("box", "min = [0, 0, 0]\nmax = [1e150, 1e150, 1e150]", "max"),
        ("box", "min = [0, 0, 0]\nmax = [1e308, 1e308, 1e308]", "max"),
        ("box", "min = [-1e150, 0, 0]\nmax = [1, 1, 1]", "min"),
        ("rectangle", "origin = [0, 0, 0]\nedge_u = [1e150, 0, 0]\nedge_v = [0, 0, 1e150]", "edge_u"),
        ("rectangle", "origin = [1e308, 0, 0]\nedge_u = [1, 0, 0]\nedge_v = [0, 0, 1]", "origin"),
        ("disc", "center = [0, 0, 0]\nnormal = [0, 1, 0]\nradius = 1e150", "radius"),
        ("disc", "center = [0, 0, 0]\nnormal = [0, 1, 0]\nradius = 1e308", "radius"),
        ("sphere", "center = [0, 0, 0]\nradius = 1e150", "radius"),
        ("sphere", "center = [0, 0, 0]\nradius = 1e308", "radius"),
        ("sphere", "center = [2e6, 0, 0]\nradius = 1", "center"),
    ] {
        let started = std::time::Instant::now();
        assert_error(&rejected(&surface(shape, keys)), S, key, &["out of range", "at most 1e6 m"]);
        assert!(started.elapsed().as_secs_f64() < 1.0, "{shape} {keys}: not refused at once");
    }
    // At the edge of the range: accepted (with the plausibility warning of its size).
    let scene = parse(&surface("rectangle", "origin = [-1e6, 0, 0]\nedge_u = [1e6, 0, 0]\nedge_v = [0, 0, 1e6]"))
        .unwrap_or_else(|e| panic!("{e}"));
    assert!(scene.warnings().iter().any(|w| w.key() == "shape" && w.message().contains("1 km")));
    let probe = format!("{}\n[[probe]]\nname = \"p\"\nposition = [0, 1e7, 0]\nnormal = [0, 1, 0]\n", lit(""));
    assert_error(&rejected(&probe), "[[probe]] \"p\" (#1)", "position", &["out of range"]);
}

#[test]
fn direction_counts_past_16_bit_cell_indices_are_refused_with_the_reason() {
    let with = |k: &str| {
        BASE.replace("patch_size = 0.1", &format!("patch_size = 0.1\ndirections = {k}")) + &lit("")[BASE.len()..]
    };
    for k in ["1000000000", "4294967297", "9223372036854775807", "65536"] {
        assert_error(&rejected(&with(k)), "[discretization]", "directions", &["out of range", "65535", "16-bit"]);
    }
    let scene = parse(&with("65535")).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(scene.discretization.directions, ugo::directions::Scheme::Cells(65535));
}

#[test]
fn a_scene_spanning_kilometres_of_small_surfaces_is_warned_about() {
    // A lamp 5 km from a 1 m plate: each surface is small, the scene is not.
    let far = surface("rectangle", "origin = [5000, 0, 0]\nedge_u = [1, 0, 0]\nedge_v = [0, 0, 1]");
    let scene = parse(&far).unwrap_or_else(|e| panic!("{e}"));
    let warnings = scene.warnings();
    let span =
        warnings.iter().find(|w| w.message().contains("the scene spans")).unwrap_or_else(|| panic!("{warnings:?}"));
    assert!(span.message().contains("millimetres") && span.message().contains("5.0"), "{span}");
    // A room of metres is not.
    let near = surface("rectangle", "origin = [5, 0, 0]\nedge_u = [1, 0, 0]\nedge_v = [0, 0, 1]");
    assert!(parse(&near).unwrap().warnings().is_empty());
}
