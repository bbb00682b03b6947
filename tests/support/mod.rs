//! Scenes built in code for the tests (no case file involved).

use glam::DVec3;
use std::path::PathBuf;
use ugo::directions::DirectionSet;
use ugo::model::{Model, ModelOptions};
use ugo::scene::{Discretization, Emission, Material, MaterialModel, Scene, Shape, SolverSettings, Surface};

pub fn lambert(name: &str, reflectance: f64) -> Material {
    Material { name: name.into(), model: MaterialModel::Lambert { reflectance, transmittance: 0.0 } }
}

pub fn surface(name: &str, shape: Shape, material: usize, inside: bool, emission: Option<Emission>) -> Surface {
    Surface { name: name.into(), shape, material, two_sided: false, inside, emission }
}

pub fn scene(materials: Vec<Material>, surfaces: Vec<Surface>, patch_size: f64) -> Scene {
    Scene {
        path: PathBuf::from("test.toml"),
        source: String::new(),
        name: "test".into(),
        description: String::new(),
        discretization: Discretization { patch_size, directions: "1".into() },
        solver: SolverSettings::default(),
        materials,
        surfaces,
        probes: Vec::new(),
    }
}

/// A closed cube of side `side` seen from inside, every face emitting `luminance`.
pub fn furnace(side: f64, reflectance: f64, luminance: f64, patch_size: f64) -> Scene {
    let shape = Shape::Box { min: DVec3::ZERO, max: DVec3::splat(side), rotate_y_deg: 0.0 };
    scene(
        vec![lambert("grey", reflectance)],
        vec![surface("room", shape, 0, true, Some(Emission::Luminance(luminance)))],
        patch_size,
    )
}

pub fn build(scene: &Scene) -> Model {
    Model::build(scene, &ModelOptions::of(scene), &|_| {}, &|_| {}).expect("model fits in memory")
}

/// The model of `scene` with another direction set.
pub fn build_with(scene: &Scene, directions: DirectionSet) -> Model {
    let options = ModelOptions { directions, ..ModelOptions::of(scene) };
    Model::build(scene, &options, &|_| {}, &|_| {}).expect("model fits in memory")
}

/// A closed cube of `material`, every face emitting `luminance`.
pub fn furnace_of(material: MaterialModel, luminance: f64, patch_size: f64) -> Scene {
    let mut s = furnace(1.0, 0.5, luminance, patch_size);
    s.materials[0].model = material;
    s
}
