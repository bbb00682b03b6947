//! Case files that parse but break a rule of `docs/design.md` §7: each error names the
//! table and the key.

use super::{BASE, CASE, LAMP, assert_error, lit, parse, rejected};
use crate::support::scratch;
use std::path::Path;
use ugo::scene::Scene;

/// A `[[surface]]` named `s` (surface #2 after the lamp) with the given shape keys.
fn surface(shape: &str, keys: &str) -> String {
    lit(&format!("\n[[surface]]\nname = \"s\"\nshape = \"{shape}\"\nmaterial = \"white\"\n{keys}\n"))
}

/// The table label of surface `s`.
const S: &str = "[[surface]] \"s\" (#2)";

const RECTANGLE: &str = "origin = [0, 0, 0]\nedge_u = [1, 0, 0]\nedge_v = [0, 1, 0]";

#[test]
fn display_names_file_table_and_key() {
    let error = rejected(&format!("{}{LAMP}", BASE.replace("0.75", "1.2")));
    let shown = error.to_string();
    let place = "cases/test.toml: [[material]] \"white\" (#1), key `reflectance`: ";
    assert!(shown.contains(place), "{shown}");
    assert!(shown.contains("must be at most 1, got 1.2"), "{shown}");
}

#[test]
fn reflectance_above_one_is_rejected() {
    let error = rejected(&format!("{}{LAMP}", BASE.replace("0.75", "1.2")));
    assert_error(&error, "[[material]] \"white\" (#1)", "reflectance", &["at most 1", "1.2"]);
}

#[test]
fn negative_reflectance_is_rejected() {
    let error = rejected(&format!("{}{LAMP}", BASE.replace("0.75", "-0.1")));
    assert_error(&error, "[[material]] \"white\" (#1)", "reflectance", &["at least 0"]);
}

#[test]
fn nan_reflectance_is_rejected() {
    let error = rejected(&format!("{}{LAMP}", BASE.replace("0.75", "nan")));
    assert_error(&error, "[[material]] \"white\" (#1)", "reflectance", &["finite", "NaN"]);
}

#[test]
fn infinite_coordinate_is_rejected() {
    let keys = RECTANGLE.replace("origin = [0, 0, 0]", "origin = [0, inf, 0]");
    let error = rejected(&surface("rectangle", &keys));
    assert_error(&error, S, "origin", &["finite", "inf"]);
}

#[test]
fn unknown_material_type_is_rejected() {
    let error = rejected(&format!("{}{LAMP}", BASE.replace("lambert", "velvet")));
    assert_error(&error, "[[material]] \"white\" (#1)", "type", &["velvet", "lambert", "phong", "mirror", "ggx"]);
}

#[test]
fn a_missing_material_key_is_named() {
    let text = format!("{}{LAMP}", BASE.replace("reflectance = 0.75\n", ""));
    let error = rejected(&text);
    assert_error(&error, "[[material]] \"white\" (#1)", "reflectance", &["needs"]);
}

#[test]
fn a_key_of_another_material_type_is_named() {
    let text = format!("{}{LAMP}", BASE.replace("reflectance = 0.75\n", "reflectance = 0.75\nexponent = 10\n"));
    let error = rejected(&text);
    assert_error(&error, "[[material]] \"white\" (#1)", "exponent", &["lambert", "reflectance, transmittance"]);
}

#[test]
fn reflectance_and_transmittance_may_not_exceed_one() {
    let text = format!("{}{LAMP}", BASE.replace("reflectance = 0.75\n", "reflectance = 0.75\ntransmittance = 0.5\n"));
    let error = rejected(&text);
    assert_error(&error, "[[material]] \"white\" (#1)", "transmittance", &["exceeds 1"]);
}

#[test]
fn missing_material_is_named_with_the_known_ones() {
    let text = surface("rectangle", RECTANGLE).replace("material = \"white\"\norigin", "material = \"red\"\norigin");
    let error = rejected(&text);
    assert_error(&error, S, "material", &["\"red\"", "\"white\""]);
}

#[test]
fn duplicate_surface_names_are_rejected() {
    let error = rejected(&format!("{BASE}{LAMP}{LAMP}"));
    assert_error(&error, "[[surface]] \"lamp\" (#2)", "name", &["duplicate", "#1"]);
}

#[test]
fn duplicate_material_names_are_rejected() {
    let error = rejected(&format!("{BASE}{BASE}{LAMP}").replacen("[discretization]\npatch_size = 0.1\n", "", 1));
    assert_error(&error, "[[material]] \"white\" (#2)", "name", &["duplicate"]);
}

#[test]
fn duplicate_probe_names_are_rejected() {
    let probe = "\n[[probe]]\nname = \"p\"\nposition = [0, 0, 0]\nnormal = [0, 1, 0]\n";
    let error = rejected(&lit(&format!("{probe}{probe}")));
    assert_error(&error, "[[probe]] \"p\" (#2)", "name", &["duplicate"]);
}

#[test]
fn zero_probe_normal_is_rejected() {
    let probe = "\n[[probe]]\nname = \"p\"\nposition = [0, 0, 0]\nnormal = [0, 0, 0]\n";
    let error = rejected(&lit(probe));
    assert_error(&error, "[[probe]] \"p\" (#1)", "normal", &["non-zero"]);
}

#[test]
fn empty_scene_is_rejected() {
    let error = rejected(BASE);
    assert_error(&error, "[[surface]]", "", &["no [[surface]]"]);
}

#[test]
fn scene_without_materials_is_rejected() {
    let error = rejected(&format!("[discretization]\npatch_size = 0.1\n{LAMP}"));
    assert_error(&error, "[[material]]", "", &["no [[material]]"]);
}

#[test]
fn missing_discretization_is_rejected() {
    let error = rejected(&format!("{}{LAMP}", BASE.replace("[discretization]\npatch_size = 0.1\n", "")));
    assert_error(&error, "[discretization]", "", &["required"]);
}

#[test]
fn non_positive_patch_size_is_rejected() {
    let error = rejected(&format!("{}{LAMP}", BASE.replace("0.1", "0")));
    assert_error(&error, "[discretization]", "patch_size", &["greater than 0"]);
}

#[test]
fn solver_settings_are_checked() {
    let error = rejected(&lit("[solver]\ntolerance = 1.0\n"));
    assert_error(&error, "[solver]", "tolerance", &["less than 1"]);
    let error = rejected(&lit("[solver]\nmax_iterations = 0\n"));
    assert_error(&error, "[solver]", "max_iterations", &["at least 1"]);
}

#[test]
fn scene_without_an_emitter_is_rejected() {
    let error = rejected(&surface("rectangle", RECTANGLE).replace("luminance = 100.0", "luminance = 0"));
    assert_error(&error, "", "emission", &["nothing emits light"]);
    let error = rejected(&format!(
        "{BASE}\n[[surface]]\nname = \"s\"\nshape = \"sphere\"\nmaterial = \"white\"\ncenter = [0, 0, 0]\nradius = 1\n"
    ));
    assert!(error.message().contains("nothing emits light"), "{error}");
}

#[test]
fn emission_with_luminance_and_flux_is_rejected() {
    let text = lit("").replace("{ luminance = 100.0 }", "{ luminance = 100.0, flux = 5 }");
    let error = rejected(&text);
    assert_error(&error, "[[surface]] \"lamp\" (#1)", "emission", &["not both"]);
}

#[test]
fn empty_emission_is_rejected() {
    let error = rejected(&lit("").replace("{ luminance = 100.0 }", "{}"));
    assert_error(&error, "[[surface]] \"lamp\" (#1)", "emission", &["luminance", "flux"]);
}

#[test]
fn negative_flux_is_rejected() {
    let error = rejected(&lit("").replace("{ luminance = 100.0 }", "{ flux = -1 }"));
    assert_error(&error, "[[surface]] \"lamp\" (#1)", "emission.flux", &["at least 0"]);
}

#[test]
fn key_of_another_shape_is_rejected() {
    let error = rejected(&surface("rectangle", &format!("{RECTANGLE}\nradius = 1")));
    assert_error(&error, S, "radius", &["rectangle", "origin"]);
}

#[test]
fn missing_shape_key_is_named() {
    let error = rejected(&surface("rectangle", "origin = [0, 0, 0]\nedge_u = [1, 0, 0]"));
    assert_error(&error, S, "edge_v", &["missing", "rectangle"]);
}

#[test]
fn unknown_shape_is_rejected() {
    let error = rejected(&surface("cylinder", ""));
    assert_error(&error, S, "shape", &["cylinder", "sphere"]);
}

#[test]
fn degenerate_rectangles_are_rejected() {
    let zero = RECTANGLE.replace("edge_u = [1, 0, 0]", "edge_u = [0, 0, 0]");
    assert_error(&rejected(&surface("rectangle", &zero)), S, "edge_u", &["non-zero"]);
    let parallel = RECTANGLE.replace("edge_v = [0, 1, 0]", "edge_v = [-2, 0, 0]");
    assert_error(&rejected(&surface("rectangle", &parallel)), S, "edge_v", &["parallel"]);
}

#[test]
fn collinear_polygon_is_rejected() {
    let keys = "vertices = [[0, 0, 0], [1, 1, 1], [2, 2, 2], [3, 3, 3]]";
    assert_error(&rejected(&surface("polygon", keys)), S, "vertices", &["line"]);
}

#[test]
fn non_planar_polygon_is_rejected() {
    let keys = "vertices = [[0, 0, 0], [1, 0, 0], [1, 1, 0.1], [0, 1, 0]]";
    assert_error(&rejected(&surface("polygon", keys)), S, "vertices", &["planar", "#"]);
}

#[test]
fn nearly_planar_polygon_is_accepted() {
    let keys = "vertices = [[0, 0, 0], [1, 0, 0], [1, 1, 1e-9], [0, 1, 0]]";
    assert!(parse(&surface("polygon", keys)).is_ok());
}

#[test]
fn other_degenerate_polygons_are_rejected() {
    let two = "vertices = [[0, 0, 0], [1, 0, 0]]";
    assert_error(&rejected(&surface("polygon", two)), S, "vertices", &["at least 3"]);
    let repeated = "vertices = [[0, 0, 0], [1, 0, 0], [1, 0, 0], [0, 1, 0]]";
    assert_error(&rejected(&surface("polygon", repeated)), S, "vertices", &["#2 and #3 coincide"]);
    let closed = "vertices = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 0]]";
    assert_error(&rejected(&surface("polygon", closed)), S, "vertices", &["#4 and #1 coincide"]);
    let bow_tie = "vertices = [[0, 0, 0], [1, 1, 0], [1, 0, 0], [0, 1, 0]]";
    assert_error(&rejected(&surface("polygon", bow_tie)), S, "vertices", &["zero area"]);
    let nan = "vertices = [[0, 0, 0], [1, 0, 0], [0, nan, 0]]";
    assert_error(&rejected(&surface("polygon", nan)), S, "vertices", &["finite"]);
}

#[test]
fn inverted_box_is_rejected() {
    let keys = "min = [0, 0, 0]\nmax = [1, 0, 1]";
    assert_error(&rejected(&surface("box", keys)), S, "max", &["every axis"]);
}

#[test]
fn degenerate_discs_and_spheres_are_rejected() {
    let flat = "center = [0, 0, 0]\nnormal = [0, 0, 0]\nradius = 1";
    assert_error(&rejected(&surface("disc", flat)), S, "normal", &["non-zero"]);
    let point = "center = [0, 0, 0]\nradius = 0";
    assert_error(&rejected(&surface("sphere", point)), S, "radius", &["greater than 0"]);
}

#[test]
fn missing_obj_file_names_the_resolved_path() {
    let error = rejected(&surface("mesh", "file = \"models/missing.obj\""));
    let resolved = Path::new("cases").join("models").join("missing.obj");
    assert_error(&error, S, "file", &[&resolved.display().to_string()]);
}

#[test]
fn obj_without_usable_triangles_is_rejected() {
    let dir = scratch("bad-obj");
    dir.write("points.obj", "v 0 0 0\nv 1 0 0\n");
    dir.write("flat.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n");
    for (file, fragment) in [("points.obj", "no triangles"), ("flat.obj", "zero area")] {
        let text = surface("mesh", &format!("file = \"{file}\""));
        let case = dir.join("case.toml");
        let error = Scene::parse(&case, text).expect_err("no usable triangles");
        assert_eq!(error.file(), case);
        assert_eq!((error.table(), error.key()), (S, "file"), "{error}");
        assert!(error.message().contains(fragment), "{error}");
        assert!(error.message().contains(file), "{error}");
    }
}

#[test]
fn non_positive_mesh_scale_is_rejected() {
    let error = rejected(&surface("mesh", "file = \"m.obj\"\nscale = -1"));
    assert_error(&error, S, "scale", &["greater than 0"]);
    assert_eq!(error.file(), Path::new(CASE));
}

/// A `[[camera]]` named `c` at the origin looking down −z, with extra keys.
fn camera(keys: &str) -> String {
    lit(&format!("\n[[camera]]\nname = \"c\"\nposition = [0, 0, 1]\nlook_at = [0, 0, 0]\n{keys}\n"))
}

#[test]
fn camera_defaults_and_rules() {
    let scene = parse(&camera("")).unwrap();
    let c = &scene.cameras[0];
    assert_eq!((c.fov_deg, c.resolution, c.samples, c.up), (40.0, [512, 512], 4, glam::DVec3::Y));
    let at = "[[camera]] \"c\" (#1)";
    assert_error(&rejected(&camera("fov_deg = 180")), at, "fov_deg", &["less than 180"]);
    assert_error(&rejected(&camera("up = [0, 0, 2]")), at, "up", &["parallel"]);
    assert_error(&rejected(&camera("resolution = [0, 10]")), at, "resolution", &["pixel counts"]);
    assert_error(&rejected(&camera("samples = 0")), at, "samples", &["from 1"]);
    let blind = lit("\n[[camera]]\nname = \"c\"\nposition = [0, 0, 0]\nlook_at = [0, 0, 0]\n");
    assert_error(&rejected(&blind), at, "look_at", &["differ"]);
    let twice = format!("{}{}", camera(""), "\n[[camera]]\nname = \"c\"\nposition = [0, 0, 1]\nlook_at = [0, 0, 0]\n");
    assert_error(&rejected(&twice), "[[camera]] \"c\" (#2)", "name", &["duplicate"]);
    let typo = rejected(&camera("fov = 30"));
    assert!(typo.to_string().contains("unknown field `fov`"), "{typo}");
}

/// A `[[grid]]` named `g`, 2 × 1 m in the floor plane, with extra keys.
fn grid(keys: &str) -> String {
    let table = "\n[[grid]]\nname = \"g\"\norigin = [0, 0, 0]\nedge_u = [2, 0, 0]\nedge_v = [0, 0, 1]\n";
    lit(&format!("{table}{keys}\n"))
}

#[test]
fn grid_defaults_and_rules() {
    let scene = parse(&grid("resolution = [4, 2]")).unwrap();
    let g = &scene.grids[0];
    assert_eq!((g.resolution, g.normal), ([4, 2], glam::DVec3::NEG_Y), "the normal defaults to edge_u × edge_v");
    let up = parse(&grid("resolution = [4, 2]\nnormal = [0, 3, 0]")).unwrap();
    assert_eq!(up.grids[0].normal, glam::DVec3::Y);
    let at = "[[grid]] \"g\" (#1)";
    assert_error(&rejected(&grid("resolution = [0, 2]")), at, "resolution", &["from 1 to 1000", "[0, 2]"]);
    assert_error(&rejected(&grid("resolution = [4, 2]\nnormal = [1, 1, 0]")), at, "normal", &["perpendicular"]);
    let flat = grid("resolution = [4, 2]").replace("edge_v = [0, 0, 1]", "edge_v = [4, 0, 0]");
    assert_error(&rejected(&flat), at, "edge_v", &["parallel"]);
    let missing = rejected(&grid(""));
    assert_error(&missing, at, "resolution", &["is missing", "work_plane"]);
}

/// A huge or tiny number is quoted in exponent form, not with hundreds of digits (issue 37,
/// point 7).
#[test]
fn huge_and_tiny_numbers_are_quoted_in_exponent_form() {
    let error = rejected(&lit("[solver]\ntolerance = 1e308\n"));
    assert_error(&error, "[solver]", "tolerance", &["got 1e308"]);
    assert!(error.message().len() < 80, "{error}");
    let error = rejected(&format!("{LAMP}{}", BASE.replace("patch_size = 0.1", "patch_size = -1e-300")));
    assert!(error.to_string().contains("got -1e-300") && error.to_string().len() < 200, "{error}");
    let error = rejected(&lit("[solver]\ntolerance = 2\n"));
    assert_error(&error, "[solver]", "tolerance", &["got 2"]);
}
