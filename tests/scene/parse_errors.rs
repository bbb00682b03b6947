//! Case files that toml/serde reject (unknown keys, wrong types, missing keys, bad syntax)
//! give errors naming the file, the line, the table and the key.

use super::{BASE, LAMP, assert_error, lit, rejected};

#[test]
fn misspelled_material_key_is_named() {
    let text = format!("{}{LAMP}", BASE.replace("reflectance", "reflectanse"));
    let error = rejected(&text);
    assert_error(&error, "[[material]] #1", "reflectanse", &["line 8", "unknown field"]);
    let shown = error.to_string();
    assert!(shown.starts_with("cases/test.toml: [[material]] #1, key `reflectanse`: line 8"));
}

#[test]
fn misspelled_key_in_a_later_surface_names_that_surface() {
    let wall = r#"
[[surface]]
name = "wall"
shape = "rectangle"
material = "white"
orgin = [0, 0, 0]
"#;
    let error = rejected(&lit(wall));
    assert_error(&error, "[[surface]] #2", "orgin", &["unknown field `orgin`"]);
}

#[test]
fn misspelled_key_in_an_inline_table_is_dotted() {
    let text = lit("").replace("{ luminance = 100.0 }", "{ luminanse = 100.0 }");
    let error = rejected(&text);
    assert_error(&error, "[[surface]] #1", "emission.luminanse", &["unknown field"]);
}

#[test]
fn misspelled_top_level_key_is_named() {
    let error = rejected(&lit("[solver]\ntolerance = 1e-6\nmax_iteration = 10\n"));
    assert_error(&error, "[solver]", "max_iteration", &["unknown field"]);
}

#[test]
fn wrong_type_names_the_key() {
    let text = lit("").replace("radius = 0.2", "radius = \"big\"");
    let error = rejected(&text);
    assert_error(&error, "[[surface]] #1", "radius", &["invalid type"]);
}

#[test]
fn wrong_type_inside_an_inline_table_is_dotted() {
    let text = lit("").replace("{ luminance = 100.0 }", "{ luminance = true }");
    let error = rejected(&text);
    assert_error(&error, "[[surface]] #1", "emission.luminance", &["invalid type"]);
}

#[test]
fn bad_element_of_a_multi_line_array_names_the_array() {
    let poly = r#"
[[surface]]
name = "poly"
shape = "polygon"
material = "white"
vertices = [
    [0, 0, 0],
    [1, 0],
    [0, 1, 0],
]
"#;
    let error = rejected(&lit(poly));
    assert_error(&error, "[[surface]] #2", "vertices", &["length"]);
}

#[test]
fn missing_required_key_is_named() {
    let text = format!("{}{LAMP}", BASE.replace("patch_size = ", "patch_sise = "));
    let error = rejected(&text);
    assert_error(&error, "[discretization]", "patch_sise", &["unknown field"]);
}

#[test]
fn unknown_table_is_rejected() {
    let error = rejected(&lit("[surfaces]\nname = \"x\"\n"));
    assert_eq!(error.key(), "surfaces", "{error}");
    assert!(error.message().contains("unknown field"), "{error}");
}

#[test]
fn syntax_error_gives_the_line() {
    let error = rejected("[discretization]\npatch_size = = 0.1\n");
    assert_error(&error, "[discretization]", "patch_size", &["line 2"]);
}

#[test]
fn repeated_table_is_rejected_at_its_header() {
    let error = rejected(&lit("[discretization]\npatch_size = 1\n"));
    assert_error(&error, "[discretization]", "", &["line 18", "duplicate"]);
}
