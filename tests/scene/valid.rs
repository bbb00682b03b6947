//! Valid case files parse into the right runtime values.

use super::{BASE, lit, parse};
use crate::support::scratch;
use glam::DVec3;
use ugo::geometry::{Emission, Shape};
use ugo::material::MaterialModel;
use ugo::scene::Scene;

const EVERY_SHAPE: &str = r#"
[scene]
name = "Every shape"
description = "one surface of each shape"

[discretization]
patch_size = 0.05

[solver]
tolerance = 1e-6
max_iterations = 500

[[material]]
name = "white"
type = "lambert"
reflectance = 0.75

[[material]]
name = "black"
type = "lambert"
reflectance = 0

[[surface]]
name = "floor"
shape = "rectangle"
material = "white"
inside = true
origin = [0, 0, 0]
edge_u = [1, 0, 0]
edge_v = [0, 0, -1]

[[surface]]
name = "triangle"
shape = "polygon"
material = "black"
two_sided = true
vertices = [
    [0, 0, 0],
    [1, 0, 0],
    [0, 1, 0],
]

[[surface]]
name = "crate"
shape = "box"
material = "white"
min = [0, 0, 0]
max = [1, 2, 3]
rotate_y_deg = 15

[[surface]]
name = "lamp"
shape = "disc"
material = "white"
center = [0, 2, 0]
normal = [0, -2, 0]
radius = 0.25
emission = { luminance = 1000 }

[[surface]]
name = "ball"
shape = "sphere"
material = "white"
center = [1, 1, 1]
radius = 0.5
emission = { flux = 20.5 }

[[surface]]
name = "statue"
shape = "mesh"
material = "black"
file = "model.obj"
scale = 2.0
translate = [0, 0, 1]

[[probe]]
name = "floor centre"
position = [0.5, 0, -0.5]
normal = [0, 3, 0]
"#;

/// A unit square (two triangles once triangulated) and a zero-area triangle.
const OBJ: &str = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nf 1 2 3 4\nf 1 2 5\n";

fn every_shape() -> Scene {
    let dir = scratch("every-shape");
    dir.write("model.obj", OBJ);
    let case = dir.write("case.toml", EVERY_SHAPE);
    Scene::parse(&case, EVERY_SHAPE.to_string()).expect("valid scene")
}

#[test]
fn header_tables_are_read() {
    let scene = every_shape();
    assert_eq!(scene.name, "Every shape");
    assert_eq!(scene.description, "one surface of each shape");
    assert_eq!(scene.source, EVERY_SHAPE);
    // no `kernel`: the kernel is chosen by size, from the patch size as read
    assert_eq!(scene.discretization.chosen_by_size.map(|a| a.patch_size), Some(0.05));
    assert_eq!(scene.solver.tolerance, 1e-6);
    assert_eq!(scene.solver.max_iterations, 500);
    let reflectances: Vec<_> = scene.materials.iter().map(|m| (&m.name[..], &m.model)).collect();
    assert_eq!(
        reflectances,
        [
            ("white", &MaterialModel::Lambert { reflectance: 0.75, transmittance: 0.0 }),
            ("black", &MaterialModel::Lambert { reflectance: 0.0, transmittance: 0.0 }),
        ]
    );
}

#[test]
fn surfaces_keep_their_common_keys() {
    let scene = every_shape();
    let names: Vec<_> = scene.surfaces.iter().map(|s| &s.name[..]).collect();
    assert_eq!(names, ["floor", "triangle", "crate", "lamp", "ball", "statue"]);
    let materials: Vec<_> = scene.surfaces.iter().map(|s| s.material).collect();
    assert_eq!(materials, [0, 1, 0, 0, 0, 1]);
    let floor = &scene.surfaces[0];
    assert!(floor.inside && !floor.two_sided);
    let triangle = &scene.surfaces[1];
    assert!(triangle.two_sided && !triangle.inside);
    assert_eq!(scene.surfaces[0].emission, None);
    assert_eq!(scene.surfaces[3].emission, Some(Emission::Luminance(1000.0)));
    assert_eq!(scene.surfaces[4].emission, Some(Emission::Flux(20.5)));
    assert_eq!(scene.surface_index("ball"), Some(4));
}

#[test]
fn analytic_shapes_are_read() {
    let scene = every_shape();
    let shapes: Vec<_> = scene.surfaces.iter().map(|s| &s.shape).collect();
    assert_eq!(
        shapes[..5],
        [
            &Shape::Rectangle { origin: DVec3::ZERO, edge_u: DVec3::X, edge_v: DVec3::NEG_Z },
            &Shape::Polygon { vertices: vec![DVec3::ZERO, DVec3::X, DVec3::Y] },
            &Shape::Box { min: DVec3::ZERO, max: DVec3::new(1.0, 2.0, 3.0), rotate_y_deg: 15.0 },
            &Shape::Disc { center: DVec3::new(0.0, 2.0, 0.0), normal: DVec3::NEG_Y, radius: 0.25 },
            &Shape::Sphere { center: DVec3::ONE, radius: 0.5 },
        ]
    );
}

#[test]
fn mesh_is_loaded_scaled_translated_and_cleaned() {
    let scene = every_shape();
    let Shape::Mesh { file, triangles } = &scene.surfaces[5].shape else {
        panic!("not a mesh: {:?}", scene.surfaces[5].shape);
    };
    assert!(file.ends_with("model.obj"), "{file:?}");
    assert_eq!(triangles.len(), 2, "the zero-area triangle is dropped");
    let z = DVec3::Z;
    let corners: Vec<DVec3> = triangles.iter().flatten().copied().collect();
    for corner in [z, 2.0 * DVec3::X + z, 2.0 * DVec3::ONE - z, 2.0 * DVec3::Y + z] {
        assert!(corners.contains(&corner), "{corner} missing from {corners:?}");
    }
}

#[test]
fn probes_are_read_with_unit_normals() {
    let scene = every_shape();
    assert_eq!(scene.probes.len(), 1);
    assert_eq!(scene.probes[0].name, "floor centre");
    assert_eq!(scene.probes[0].position, DVec3::new(0.5, 0.0, -0.5));
    assert_eq!(scene.probes[0].normal, DVec3::Y);
}

#[test]
fn optional_keys_take_their_defaults() {
    let box_ = "[[surface]]\nname = \"b\"\nshape = \"box\"\nmaterial = \"white\"\nmin = [0, 0, 0]\nmax = [1, 1, 1]\n";
    let scene = parse(&lit(box_)).expect("valid scene");
    assert_eq!(scene.name, "test", "the name defaults to the file stem");
    assert_eq!(scene.description, "");
    assert_eq!(scene.solver, Default::default());
    assert!(scene.probes.is_empty());
    let lamp = &scene.surfaces[0];
    assert!(!lamp.two_sided && !lamp.inside);
    let Shape::Box { rotate_y_deg, .. } = scene.surfaces[1].shape else { panic!("not a box") };
    assert_eq!(rotate_y_deg, 0.0);
}

#[test]
fn integers_are_accepted_as_numbers() {
    let text = BASE.replace("0.75", "1").replace("0.1", "1");
    let scene = parse(&format!("{text}{}", super::LAMP)).expect("valid scene");
    assert_eq!(scene.materials[0].model, MaterialModel::Lambert { reflectance: 1.0, transmittance: 0.0 });
    assert_eq!(scene.discretization.patch_size, 1.0);
}

#[test]
fn documented_example_is_valid() {
    let doc = include_str!("../../docs/scene-format.md");
    let example = doc
        .split_once("```toml\n")
        .and_then(|(_, rest)| rest.split_once("```"))
        .map(|(toml, _)| toml)
        .expect("docs/scene-format.md has a ```toml example");
    let scene = parse(example).expect("the documented example is valid");
    assert_eq!(scene.name, "Small room");
    assert_eq!(scene.surfaces.len(), 4);
    assert_eq!(scene.surfaces[1].emission, Some(Emission::Flux(1000.0)));
}
