//! Degenerate geometry that used to be meshed into the wrong area or to nothing is
//! refused, naming the surface and the key (issue 18, item 6); simple concave polygons
//! are still accepted.

use super::{LAMP, assert_error, lit, parse, rejected};
use crate::support::scratch;
use ugo::geometry::Shape;

/// A `[[surface]]` named `s` (surface #2 after the lamp) with the given shape keys.
fn surface(shape: &str, keys: &str) -> String {
    lit(&format!("\n[[surface]]\nname = \"s\"\nshape = \"{shape}\"\nmaterial = \"white\"\n{keys}\n"))
}

const S: &str = "[[surface]] \"s\" (#2)";

fn polygon(vertices: &[[f64; 2]]) -> String {
    let v: Vec<String> = vertices.iter().map(|[x, z]| format!("[{x}, 0, {z}]")).collect();
    surface("polygon", &format!("vertices = [{}]", v.join(", ")))
}

#[test]
fn self_intersecting_polygons_are_refused() {
    // A bow tie with lobes of different areas (so its signed area is not zero).
    let bow_tie = polygon(&[[0.0, 0.0], [2.0, 2.0], [2.0, 0.0], [0.0, 1.0]]);
    assert_error(&rejected(&bow_tie), S, "vertices", &["not a simple polygon", "edge #1", "edge #3", "cross"]);
    let star: Vec<[f64; 2]> = (0..5)
        .map(|k| {
            let a = (90.0 + 144.0 * k as f64).to_radians();
            [a.cos(), a.sin()]
        })
        .collect();
    assert_error(&rejected(&polygon(&star)), S, "vertices", &["not a simple polygon", "cross"]);
    // Pinched: the outline passes twice through (1, 1).
    let pinched = polygon(&[[0.0, 0.0], [2.0, 0.0], [1.0, 1.0], [2.0, 2.0], [0.0, 2.0], [1.0, 1.0]]);
    assert_error(&rejected(&pinched), S, "vertices", &["not a simple polygon", "touch"]);
    // A vertex on a non-adjacent edge.
    let touching = polygon(&[[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [1.0, 0.0], [0.0, 2.0]]);
    assert_error(&rejected(&touching), S, "vertices", &["not a simple polygon", "touch"]);
    // Folding back: (2, 2) → (2, 1) runs back along the edge that reached (2, 2).
    let fold = polygon(&[[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [2.0, 1.0], [0.0, 2.0]]);
    assert_error(&rejected(&fold), S, "vertices", &["folds back", "vertex #3"]);
}

#[test]
fn simple_concave_polygons_are_accepted() {
    let l = [[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [1.0, 1.0], [1.0, 2.0], [0.0, 2.0]];
    let u = [[0.0, 0.0], [3.0, 0.0], [3.0, 2.0], [2.0, 2.0], [2.0, 1.0], [1.0, 1.0], [1.0, 2.0], [0.0, 2.0]];
    let notch = [[0.0, 0.0], [4.0, 0.0], [4.0, 3.0], [2.5, 3.0], [2.5, 2.5], [1.5, 2.5], [1.5, 3.0], [0.0, 3.0]];
    let collinear = [[0.0, 0.0], [1.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]];
    for v in [&l[..], &u, &notch, &collinear] {
        parse(&polygon(v)).unwrap_or_else(|e| panic!("{v:?}: {e}"));
        let reversed: Vec<[f64; 2]> = v.iter().rev().copied().collect();
        parse(&polygon(&reversed)).unwrap_or_else(|e| panic!("{reversed:?}: {e}"));
    }
}

#[test]
fn a_surface_that_meshes_to_no_patch_is_an_error_naming_it() {
    let tiny = "center = [0, 1, 0]\nnormal = [0, 1, 0]\nradius = 1e-300\nemission = { flux = 100 }";
    assert_error(&rejected(&surface("disc", tiny)), S, "radius", &["meshes to no patch", "too small"]);
    let huge = "center = [0, 0, 0]\nradius = 1e200";
    assert_error(&rejected(&surface("sphere", huge)), S, "radius", &["out of range", "1e6 m"]);
    let speck = "origin = [0, 0, 0]\nedge_u = [1e-170, 0, 0]\nedge_v = [0, 0, 1e-170]";
    assert_error(&rejected(&surface("rectangle", speck)), S, "shape", &["meshes to no patch", "too small"]);
    // Small but representable is accepted (a plausibility warning is another matter).
    parse(&surface("disc", "center = [0, 1, 0]\nnormal = [0, 1, 0]\nradius = 1e-6")).unwrap();
}

#[test]
fn obj_vertices_are_read_in_double_precision() {
    let dir = scratch("obj-f64");
    dir.write("model.obj", "v 0.1 0 0\nv 1e39 0 0\nv 0.1 0 1e39\nf 1 2 3\n");
    let text = format!("{}{LAMP}", lit("").split(LAMP).next().unwrap())
        + "\n[[surface]]\nname = \"s\"\nshape = \"mesh\"\nmaterial = \"white\"\nfile = \"model.obj\"\n";
    // 1e39 is a finite f64, read as such, but lies beyond the scene's range of coordinates.
    let case = dir.write("case.toml", &text);
    let error = ugo::scene::Scene::parse(&case, text.clone()).expect_err("a vertex at 1e39 m accepted");
    assert_eq!(error.key(), "scale", "{error}");
    assert!(error.message().contains("out of range") && error.message().contains("[1e39, 0e0, 0e0]"), "{error}");
    let text = text + "scale = 1e-36\n";
    let case = dir.write("case.toml", &text);
    let scene = ugo::scene::Scene::parse(&case, text).expect("scaled into range");
    let Shape::Mesh { triangles, .. } = &scene.surfaces[1].shape else { panic!() };
    assert_eq!(triangles[0][0].x, 0.1 * 1e-36, "0.1 read through f32 would be 0.10000000149");
    assert_eq!(triangles[0][1].x, 1e39 * 1e-36);
}
