//! glTF triangle strips and fans (modes 5 and 6; issue 38, point 4): indexed or not, each
//! reads exactly the triangles of the equivalent triangle list, in the list's order and
//! orientation (a strip's odd triangles swapped per the glTF 2.0 specification), hence the
//! same area and the same solved field; a strip or fan of fewer than 3 vertices is an error.

use super::gltf::{CHAIR, load, triangles};
use crate::support::gltf::Document;
use crate::support::scratch;
use serde_json::json;

/// A bent ribbon: vertices 2k at (k, 0, z) and 2k + 1 at (k, 1, z), z = 0.5 at k = 2. As a
/// strip its triangles all face −z.
fn ribbon() -> Vec<[f32; 3]> {
    let z = [0.0, 0.0, 0.5];
    (0..6).map(|i| [(i / 2) as f32, (i % 2) as f32, z[i / 2]]).collect()
}

/// The ribbon's vertices read in `mode`, by the index list `indices` (none: in their order);
/// index list 0 is always there (a triangle list), so that `indices` is accessor 2.
fn ribbon_in(mode: u32, indices: Option<Vec<u32>>) -> Document {
    let mut primitive = json!({ "attributes": { "POSITION": 0 }, "mode": mode });
    let mut lists = vec![vec![0, 1, 2]];
    if let Some(list) = indices {
        primitive["indices"] = json!(2);
        lists.push(list);
    }
    let document = json!({ "scene": 0, "scenes": [{ "nodes": [0] }], "nodes": [{ "mesh": 0 }],
                           "meshes": [{ "name": "ribbon", "primitives": [primitive] }] });
    Document { positions: ribbon(), indices: lists, image: Vec::new(), document }
}

fn area(triangles: &[[glam::DVec3; 3]]) -> f64 {
    triangles.iter().map(|[a, b, c]| (b - a).cross(c - a).length() / 2.0).sum()
}

#[test]
fn strips_and_fans_read_the_triangles_of_their_lists() {
    let dir = scratch("gltf-strips");
    // Triangle i of a strip: (i, i+1, i+2), odd ones (i, i+2, i+1); of a fan: (i+1, i+2, 0).
    let strip = vec![0, 1, 2, 1, 3, 2, 2, 3, 4, 3, 5, 4];
    let fan = vec![1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 5, 0];
    let reversed = vec![5, 4, 3, 4, 2, 3, 3, 2, 1, 2, 0, 1];
    let scene_of = |name: &str, document: Document| {
        dir.write(name, &document.embedded());
        load(&dir, name, "").unwrap_or_else(|e| panic!("{name}: {e}"))
    };
    for (name, mode, indices, list) in [
        ("strip.gltf", 5, None, &strip),
        ("strip-indexed.gltf", 5, Some(vec![0, 1, 2, 3, 4, 5]), &strip),
        ("strip-reversed.gltf", 5, Some(vec![5, 4, 3, 2, 1, 0]), &reversed),
        ("fan.gltf", 6, None, &fan),
        ("fan-indexed.gltf", 6, Some(vec![0, 1, 2, 3, 4, 5]), &fan),
    ] {
        let read = scene_of(name, ribbon_in(mode, indices));
        let listed = scene_of(&format!("list-{name}"), ribbon_in(4, Some(list.clone())));
        let (got, expected) = (triangles(&read, 1), triangles(&listed, 1));
        assert_eq!(got.len(), 4, "{name}");
        assert_eq!(got, expected, "{name}: the list's triangles, bit for bit");
        assert_eq!(area(got), area(expected), "{name}");
        assert_eq!(read.surfaces.len(), listed.surfaces.len(), "{name}");
    }
    // The strip keeps one orientation: every triangle faces −z, as does the strip of six
    // vertices read backwards; without the swap of odd triangles, half would face +z.
    let facing = |name: &str| {
        let scene = load(&dir, name, "").unwrap();
        triangles(&scene, 1).iter().map(|[a, b, c]| (b - a).cross(c - a).z.signum()).collect::<Vec<f64>>()
    };
    assert_eq!(facing("strip.gltf"), [-1.0; 4]);
    assert_eq!(facing("strip-reversed.gltf"), [-1.0; 4]);
    assert!((area(triangles(&load(&dir, "strip.gltf", "").unwrap(), 1)) - (1.0 + 1.25f64.sqrt())).abs() < 1e-15);
}

#[test]
fn a_strip_or_fan_of_fewer_than_three_vertices_is_an_error() {
    let dir = scratch("gltf-short-strips");
    for (mode, name) in [(5, "TriangleStrip"), (6, "TriangleFan")] {
        dir.write("short.gltf", &ribbon_in(mode, Some(vec![0, 1])).embedded());
        let error = load(&dir, "short.gltf", "").unwrap_err();
        assert_eq!((error.table(), error.key()), (CHAIR, "file"), "{error}");
        let said = "mesh \"ribbon\" (#0), primitive #0 of the glTF file";
        assert!(error.message().contains(said) && error.message().contains("short.gltf"), "{error}");
        assert!(error.message().contains(&format!("is a {name} of 2 vertices, fewer than 3")), "{error}");
    }
}
