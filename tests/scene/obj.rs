//! `shape = "mesh"` (issue 17, item 3): an OBJ file rotated about any axis besides scaled
//! and translated, and its `usemtl` groups given ugo materials by the surface's
//! `materials` table; an unmapped OBJ material, a mapping of a name the file does not use
//! and a mapping to an unknown material are errors that name them.

use super::{BASE, LAMP, SceneError, assert_error};
use crate::support::scratch;
use glam::DVec3;
use ugo::geometry::{Emission, Shape};
use ugo::scene::Scene;

/// A case with a second material `oak` and the mesh surface `chair` of `keys`, reading
/// `obj` as `chair.obj`.
fn load(obj: &str, keys: &str) -> Result<Scene, SceneError> {
    let dir = scratch("obj");
    dir.write("chair.obj", obj);
    let text = format!(
        "{BASE}[[material]]\nname = \"oak\"\ntype = \"lambert\"\nreflectance = 0.3\n{LAMP}\n[[surface]]\nname = \"chair\"\nshape = \"mesh\"\nmaterial = \"white\"\nfile = \"chair.obj\"\n{keys}\n"
    );
    let case = dir.write("case.toml", &text);
    Scene::load(&case).map_err(|e| SceneError::new(std::path::Path::new(super::CASE), e.table(), e.key(), e.message()))
}

fn triangles(scene: &Scene, surface: usize) -> &[[DVec3; 3]] {
    match &scene.surfaces[surface].shape {
        Shape::Mesh { triangles, .. } => triangles,
        other => panic!("{other:?}"),
    }
}

const TRIANGLE: &str = "v 1 0 0\nv 0 2 0\nv 0 0 3\nf 1 2 3\n";
const CHAIR: &str = "[[surface]] \"chair\" (#2)";

#[test]
fn a_mesh_is_scaled_then_rotated_about_its_axis_then_translated() {
    let scene = load(TRIANGLE, "scale = 2\nrotate_axis = [0, 0, 5]\nrotate_deg = 90\ntranslate = [1, 1, 1]").unwrap();
    let expected = [[1.0, 3.0, 1.0], [-3.0, 1.0, 1.0], [1.0, 1.0, 7.0]].map(DVec3::from);
    let got = triangles(&scene, 1)[0];
    assert!(got.iter().zip(&expected).all(|(a, b)| (*a - *b).length() < 1e-14), "{got:?}");
    // 120° about the diagonal turns x into y, y into z and z into x.
    let scene = load(TRIANGLE, "rotate_axis = [1, 1, 1]\nrotate_deg = 120").unwrap();
    let expected = [[0.0, 1.0, 0.0], [0.0, 0.0, 2.0], [3.0, 0.0, 0.0]].map(DVec3::from);
    let got = triangles(&scene, 1)[0];
    assert!(got.iter().zip(&expected).all(|(a, b)| (*a - *b).length() < 1e-14), "{got:?}");
    assert_eq!(scene.surfaces[1].name, "chair", "one material: the surface keeps its name");
}

/// A unit square before any `usemtl`, then `seat` (one triangle of area 2), `legs` and `seat` again.
const GROUPS: &str = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nv 0 2 0\nf 1 2 3 4\nusemtl seat\nf 1 5 6\nusemtl legs\nf 1 2 3\nusemtl seat\nf 1 3 4\n";

#[test]
fn usemtl_groups_take_the_materials_the_case_maps_them_to() {
    let keys = "materials = { seat = \"oak\", legs = \"white\" }\nemission = { flux = 30 }";
    let scene = load(GROUPS, keys).unwrap();
    let names: Vec<&str> = scene.surfaces[1..].iter().map(|s| s.name.as_str()).collect();
    assert_eq!(names, ["chair/white", "chair/oak"], "one surface per ugo material, in order of first use");
    let material = |i: usize| scene.materials[scene.surfaces[i].material].name.as_str();
    assert_eq!((material(1), material(2)), ("white", "oak"));
    assert_eq!((triangles(&scene, 1).len(), triangles(&scene, 2).len()), (3, 2), "square + legs; seat twice");
    // Areas 1.5 (white) and 2.5 (oak): the flux is shared in proportion.
    let flux = |i: usize| match scene.surfaces[i].emission {
        Some(Emission::Flux(f)) => f,
        other => panic!("{other:?}"),
    };
    assert!((flux(1) - 30.0 * 1.5 / 4.0).abs() < 1e-12 && (flux(2) - 30.0 * 2.5 / 4.0).abs() < 1e-12);
    let group = &scene.lighting.groups[0];
    assert_eq!(group.surfaces, [0, 1, 2], "both parts are in the table's group");
}

#[test]
fn an_unmapped_or_unknown_obj_material_is_named() {
    let error = load(GROUPS, "").unwrap_err();
    assert_error(&error, CHAIR, "materials", &["\"seat\"", "its line 8", "does not map"]);
    let error = load(GROUPS, "materials = { seat = \"oak\" }").unwrap_err();
    let line = format!("line {}", BASE.lines().count() + LAMP.lines().count() + 11);
    assert_error(&error, CHAIR, "materials", &[&line, "\"legs\"", "its line 10"]);
    let error = load(GROUPS, "materials = { seat = \"oak\", legs = \"oak\", glass = \"white\" }").unwrap_err();
    assert_error(&error, CHAIR, "materials.glass", &["uses no material \"glass\"", "\"seat\", \"legs\""]);
    let error = load(GROUPS, "materials = { seat = \"teak\", legs = \"oak\" }").unwrap_err();
    assert_error(&error, CHAIR, "materials.seat", &["unknown material \"teak\"", "\"oak\""]);
    let error = load(TRIANGLE, "rotate_axis = [0, 0, 0]").unwrap_err();
    assert_error(&error, CHAIR, "rotate_axis", &["non-zero"]);
}
