//! The same furniture as OBJ and as glTF 2.0 (issue 38, point 4): a cube in a lit room,
//! read from either file, solves to the same field (the glTF's base colour a reflectance
//! equal to the OBJ's mapped material; both formats share one path after loading).

use crate::support::gltf::{Document, cube_corners, cube_obj, cube_triangles};
use crate::support::{build, scratch, solve};
use serde_json::json;
use ugo::scene::Scene;

/// A 3 × 2.5 × 3 m room under a bulb with a cube (grey, ρ = 0.5) read from `file`.
fn room(file: &str, keys: &str) -> String {
    format!(
        "[discretization]\npatch_size = 0.5\nkernel = \"uniform\"\n\n[[material]]\nname = \"white\"\ntype = \"lambert\"\n\
         reflectance = 0.7\n\n[[material]]\nname = \"grey\"\ntype = \"lambert\"\nreflectance = 0.5\n\n\
         [[luminaire]]\nname = \"bulb\"\ntype = \"isotropic\"\nflux = 1000\nposition = [1.5, 2.3, 1.5]\n\n\
         [[surface]]\nname = \"room\"\nshape = \"box\"\nmaterial = \"white\"\ninside = true\nmin = [0, 0, 0]\n\
         max = [3, 2.5, 3]\n\n[[surface]]\nname = \"cube\"\nshape = \"mesh\"\nmaterial = \"white\"\nfile = \"{file}\"\n\
         scale = 0.75\ntranslate = [1, 0, 1.25]\n{keys}\n"
    )
}

#[test]
fn a_cube_as_obj_and_as_gltf_solves_to_the_same_field() {
    let dir = scratch("mesh-formats");
    dir.write("cube.obj", &(String::from("usemtl paint\n") + &cube_obj()));
    let material = json!([{ "name": "paint", "pbrMetallicRoughness": { "baseColorFactor": [0.5, 0.5, 0.5, 1] } }]);
    let primitive = json!({ "attributes": { "POSITION": 0 }, "indices": 1, "material": 0 });
    let document = json!({ "scene": 0, "scenes": [{ "nodes": [0] }], "nodes": [{ "mesh": 0 }],
                           "meshes": [{ "primitives": [primitive] }], "materials": material });
    let gltf = Document { positions: cube_corners(), indices: vec![cube_triangles()], image: Vec::new(), document };
    std::fs::write(dir.join("cube.glb"), gltf.binary()).unwrap();
    let obj = Scene::load(&dir.write("obj.toml", &room("cube.obj", "materials = { paint = \"grey\" }"))).unwrap();
    let glb = Scene::load(&dir.write("glb.toml", &room("cube.glb", ""))).unwrap();
    let (a, b) = (build(&obj), build(&glb));
    assert_eq!(a.mesh.patches.len(), b.mesh.patches.len());
    let (x, y) = (solve(&a), solve(&b));
    let worst = x.iter().zip(&y).map(|(p, q)| (p - q).abs() / p.abs().max(1e-300)).fold(0.0, f64::max);
    eprintln!("{} unknowns, largest relative difference {worst:e}", x.len());
    assert!(worst < 1e-12, "{worst:e}");
    assert!(x.iter().any(|&v| v > 0.0), "the room is lit");
}
