//! `shape = "mesh"` read from glTF 2.0 (issue 38, point 4): the scene graph's transforms
//! (translation, rotation, scale, matrix, nested) put the triangles exactly where they say,
//! before the case's own scale and translation; a `.glb` and a `.gltf` beside its `.bin`
//! read as the embedded `.gltf`; a base colour is a Lambert material of its luminance
//! unless `materials` maps it; what is not read (lines, an emissive factor) and a model in
//! millimetres are warned; a broken file is an error naming it. Strips and fans:
//! `gltf_strips.rs`; base colour textures: `gltf_textures.rs`.

use super::{BASE, LAMP};
use crate::support::gltf::{Document, cube_corners, cube_triangles};
use crate::support::{Scratch, scratch};
use glam::DVec3;
use serde_json::{Value, json};
use ugo::geometry::Shape;
use ugo::material::MaterialModel;
use ugo::scene::{Scene, SceneError};

pub(super) const CHAIR: &str = "[[surface]] \"chair\" (#2)";

/// A case with a second material `oak` and the mesh surface `chair` reading `file` with `keys`.
pub(super) fn load(dir: &Scratch, file: &str, keys: &str) -> Result<Scene, SceneError> {
    let text = format!(
        "{BASE}[[material]]\nname = \"oak\"\ntype = \"lambert\"\nreflectance = 0.3\n{LAMP}\n[[surface]]\nname = \"chair\"\nshape = \"mesh\"\nmaterial = \"white\"\nfile = \"{file}\"\n{keys}\n"
    );
    Scene::load(&dir.write("case.toml", &text))
}

/// The cube (accessors 0 and 1) under the given nodes and scenes.
fn cube(document: Value) -> Document {
    Document { positions: cube_corners(), indices: vec![cube_triangles()], image: Vec::new(), document }
}

/// One mesh, the cube, in one node of `node`'s keys.
fn one_node(node: Value) -> Document {
    let mut node = node;
    node["mesh"] = json!(0);
    cube(json!({ "scene": 0, "scenes": [{ "nodes": [0] }], "nodes": [node],
                 "meshes": [{ "name": "cube", "primitives": [{ "attributes": { "POSITION": 0 }, "indices": 1 }] }] }))
}

pub(super) fn triangles(scene: &Scene, surface: usize) -> &[[DVec3; 3]] {
    match &scene.surfaces[surface].shape {
        Shape::Mesh { triangles, .. } => triangles,
        other => panic!("{other:?}"),
    }
}

/// The cube's triangles with every corner `p` sent to `f(p)`.
fn cube_through(f: impl Fn(DVec3) -> DVec3) -> Vec<[DVec3; 3]> {
    let corners: Vec<DVec3> = cube_corners().iter().map(|p| DVec3::from(p.map(f64::from))).collect();
    cube_triangles().chunks(3).map(|t| [0, 1, 2].map(|i| f(corners[t[i] as usize]))).collect()
}

#[test]
fn nested_node_transforms_place_the_triangles_exactly() {
    // Node 0: scale 2, turn 120° about [1, 1, 1] ((x, y, z) → (z, x, y)), move by x 10;
    // its child 1 (the cube): scale (1, 2, 3), move by x 1; its child 2 (the cube): a matrix
    // moving by y 5; node 3 (the cube) at the root, untransformed.
    let nodes = json!([
        { "translation": [10, 0, 0], "rotation": [0.5, 0.5, 0.5, 0.5], "scale": [2, 2, 2], "children": [1] },
        { "translation": [1, 0, 0], "scale": [1, 2, 3], "children": [2], "mesh": 0 },
        { "matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 5, 0, 1], "mesh": 0 },
        { "mesh": 0 },
    ]);
    let mesh = json!([{ "primitives": [{ "attributes": { "POSITION": 0 }, "indices": 1 }] }]);
    let document = cube(json!({ "scene": 0, "scenes": [{ "nodes": [0, 3] }], "nodes": nodes, "meshes": mesh }));
    let dir = scratch("gltf-nodes");
    dir.write("cube.gltf", &document.embedded());
    let scene = load(&dir, "cube.gltf", "scale = 0.5\ntranslate = [0, 1, 0]").unwrap();
    let case = |p: DVec3| 0.5 * p + DVec3::Y;
    let mut expected = cube_through(|p| case(DVec3::new(6.0 * p.z + 10.0, 2.0 * p.x + 2.0, 4.0 * p.y)));
    expected.extend(cube_through(|p| case(DVec3::new(6.0 * p.z + 10.0, 2.0 * p.x + 2.0, 4.0 * p.y + 20.0))));
    expected.extend(cube_through(case));
    assert_eq!(triangles(&scene, 1), expected, "node 1, node 2 (in node 1), node 3: bit for bit");
    assert_eq!(scene.surfaces[1].name, "chair", "no material in the file: the surface's own");
    assert_eq!(scene.files.len(), 1, "the glTF file, kept for the solution file");
}

#[test]
fn a_glb_and_an_external_buffer_read_as_the_embedded_gltf() {
    let document = one_node(json!({ "translation": [0.5, 0, 0.25], "rotation": [0, 0, 1, 0], "scale": [1, 0.5, 1] }));
    let dir = scratch("gltf-glb");
    dir.write("cube.gltf", &document.embedded());
    std::fs::write(dir.join("cube.glb"), document.binary()).unwrap();
    let (text, bin) = document.external("cube data.bin");
    let text = text.replace("cube data.bin", "cube%20data.bin");
    dir.write("external.gltf", &text);
    std::fs::write(dir.join("cube data.bin"), bin).unwrap();
    let embedded = load(&dir, "cube.gltf", "").unwrap();
    // 180° about z: (x, y, z) → (−x, −y, z), after the scale (1, 0.5, 1).
    let expected = cube_through(|p| DVec3::new(0.5 - p.x, -0.5 * p.y, p.z + 0.25));
    assert_eq!(triangles(&embedded, 1), expected);
    for file in ["cube.glb", "external.gltf"] {
        let scene = load(&dir, file, "").unwrap();
        assert_eq!(triangles(&scene, 1), expected, "{file}");
    }
    let external = load(&dir, "external.gltf", "").unwrap();
    let read: Vec<_> =
        external.files.iter().map(|f| f.path.file_name().unwrap().to_string_lossy().into_owned()).collect();
    assert_eq!(read, ["external.gltf", "cube data.bin"], "the buffer is kept with the case");
}

/// The cube's −z and +z faces (`paint`), −x and +x (an unnamed material), −y and +y (none).
pub(super) fn painted(extra: Value) -> Document {
    let all = cube_triangles();
    let mut materials = json!([
        { "name": "paint", "pbrMetallicRoughness": { "baseColorFactor": [0.75, 0.5, 0.25, 1] } },
        { "pbrMetallicRoughness": { "baseColorFactor": [0.5, 0.5, 0.5, 1] } },
    ]);
    if let Some(extra) = extra.as_object() {
        materials[0].as_object_mut().unwrap().extend(extra.clone());
    }
    let attributes = json!({ "POSITION": 0 });
    let primitives = json!([
        { "attributes": attributes, "indices": 1, "material": 0 },
        { "attributes": attributes, "indices": 2, "material": 1 },
        { "attributes": attributes, "indices": 3 },
    ]);
    let document = json!({ "scene": 0, "scenes": [{ "nodes": [0] }], "nodes": [{ "mesh": 0 }],
                           "meshes": [{ "name": "box", "primitives": primitives }], "materials": materials });
    Document {
        positions: cube_corners(),
        indices: all.chunks(12).map(<[u32]>::to_vec).collect(),
        image: Vec::new(),
        document,
    }
}

#[test]
fn a_base_colour_is_a_lambert_material_of_its_luminance() {
    let dir = scratch("gltf-colour");
    dir.write("box.gltf", &painted(json!({})).embedded());
    let scene = load(&dir, "box.gltf", "").unwrap();
    let names: Vec<&str> = scene.surfaces[1..].iter().map(|s| s.name.as_str()).collect();
    assert_eq!(names, ["chair/box.gltf:paint", "chair/box.gltf:#1", "chair/white"]);
    let model = |i: usize| &scene.materials[scene.surfaces[i].material].model;
    // ρ = 0.2126 R + 0.7152 G + 0.0722 B (Rec. 709 luminance) of (0.75, 0.5, 0.25).
    let MaterialModel::Lambert { reflectance, transmittance } = *model(1) else { panic!("{:?}", model(1)) };
    assert!((reflectance - 0.5351).abs() < 1e-15 && transmittance == 0.0, "{reflectance}");
    let MaterialModel::Lambert { reflectance, .. } = *model(2) else { panic!("{:?}", model(2)) };
    assert!((reflectance - 0.5).abs() < 1e-15, "a grey reflects its value: {reflectance}");
    assert_eq!(triangles(&scene, 1).len() + triangles(&scene, 2).len() + triangles(&scene, 3).len(), 12);
    // `materials` maps a glTF material by name (or `#i`), as an OBJ `usemtl`.
    let mapped = load(&dir, "box.gltf", "materials = { paint = \"oak\", \"#1\" = \"oak\" }").unwrap();
    let names: Vec<&str> = mapped.surfaces[1..].iter().map(|s| s.name.as_str()).collect();
    assert_eq!(names, ["chair/oak", "chair/white"]);
    assert_eq!(mapped.materials.len(), 2, "no material made");
    let error = load(&dir, "box.gltf", "materials = { wood = \"oak\" }").unwrap_err();
    assert_eq!((error.table(), error.key()), (CHAIR, "materials.wood"), "{error}");
    assert!(error.message().contains("glTF file") && error.message().contains("\"paint\", \"#1\""), "{error}");
}

#[test]
fn what_is_not_read_and_a_model_in_millimetres_are_warned() {
    let dir = scratch("gltf-warnings");
    let mut document = painted(json!({ "emissiveFactor": [1, 1, 1] }));
    document.document["meshes"][0]["primitives"][2]["mode"] = json!(1);
    dir.write("box.gltf", &document.embedded());
    let scene = load(&dir, "box.gltf", "").unwrap();
    let warnings: Vec<String> = scene.warnings().iter().map(|w| w.to_string()).collect();
    let said = |fragments: &[&str]| warnings.iter().any(|w| fragments.iter().all(|f| w.contains(f)));
    assert!(said(&["box.gltf", "\"paint\"", "emits: ignored"]), "{warnings:#?}");
    assert!(said(&["mesh \"box\" (#0), primitive #2", "box.gltf", "Lines", "no area", "skipped"]), "{warnings:#?}");
    assert_eq!(scene.surfaces.len(), 3, "the lamp, paint's and #1's faces; the lines skipped");
    // A cube drawn in millimetres (a node scale of 1000) in a room of metres.
    dir.write("big.gltf", &one_node(json!({ "scale": [1000, 1000, 1000] })).embedded());
    let warnings = load(&dir, "big.gltf", "").unwrap().warnings();
    let warning = warnings.iter().find(|w| w.table() == CHAIR).expect("warned");
    assert_eq!(warning.key(), "scale");
    assert!(warning.message().contains("scale = 0.001"), "{warning}");
}

#[test]
fn a_broken_gltf_is_an_error_naming_it() {
    let dir = scratch("gltf-broken");
    dir.write("text.gltf", "v 0 0 0\nf 1 2 3\n");
    let (text, bin) = one_node(json!({})).external("cube.bin");
    dir.write("missing.gltf", &text);
    dir.write("short.gltf", &text.replace("cube.bin", "short.bin"));
    std::fs::write(dir.join("short.bin"), &bin[..40]).unwrap();
    let mut far = one_node(json!({}));
    far.indices[0][5] = 99;
    dir.write("far.gltf", &far.embedded());
    let mut dangling = one_node(json!({}));
    dangling.document["meshes"][0]["primitives"][0]["indices"] = json!(7);
    dir.write("dangling.gltf", &dangling.embedded());
    // The `gltf` crate's own validation panicked on this one (found by mutating a .glb).
    dangling.document["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = json!(5);
    dir.write("no-positions.gltf", &dangling.embedded());
    let mut cycle = one_node(json!({ "children": [0] }));
    cycle.document["nodes"][0]["children"] = json!([0]);
    dir.write("cycle.gltf", &cycle.embedded());
    let bright = json!({ "pbrMetallicRoughness": { "baseColorFactor": [1.5, 0.5, 0.5, 1] } });
    dir.write("bright.gltf", &painted(bright).embedded());
    let mut empty = one_node(json!({}));
    empty.document["scenes"] = json!([{ "nodes": [] }]);
    dir.write("empty.gltf", &empty.embedded());
    let positions = "\"componentType\":5126";
    assert!(cycle.embedded().contains(positions));
    dir.write("short-ints.gltf", &one_node(json!({})).embedded().replace(positions, "\"componentType\":5123"));
    for (file, fragments) in [
        ("text.gltf", &["cannot read the glTF file"][..]),
        ("missing.gltf", &["buffer #0 of the glTF file", "cannot open", "cube.bin"]),
        ("short.gltf", &["holds 40 bytes, less than its byteLength 240"]),
        ("far.gltf", &["mesh \"cube\" (#0), primitive #0", "vertex index 99 is out of range (8 vertices)"]),
        ("dangling.gltf", &["cannot read the glTF file", "meshes[0].primitives[0].indices: Index out of bounds"]),
        ("no-positions.gltf", &["meshes[0].primitives[0].attributes.POSITION: Index out of bounds"]),
        ("cycle.gltf", &["has a cycle of nodes through node #0"]),
        ("short-ints.gltf", &["mesh \"cube\" (#0), primitive #0", "POSITION is U16 Vec3, not [F32] Vec3"]),
        ("absent.glb", &["cannot open the glTF file"]),
        ("bright.gltf", &["material \"paint\" (#0)", "baseColorFactor [1.5, 0.5, 0.5] is not within [0, 1]"]),
        ("empty.gltf", &["has no triangles in its scene"]),
    ] {
        let error = load(&dir, file, "").unwrap_err();
        eprintln!("{error}");
        assert_eq!((error.table(), error.key()), (CHAIR, "file"), "{error}");
        assert!(error.message().contains(file), "{error}");
        assert!(fragments.iter().all(|f| error.message().contains(f)), "{file}: {error}");
    }
}
