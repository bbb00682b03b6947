//! `ugo render`: pixels of known scenes, the EXR file read back, the command end to end;
//! the sky through openings and the luminaires' luminous openings as the eye sees them.

mod cli;
mod glossy;
mod junctions;
mod luminaires;
mod openings;
mod pictures;
mod pixels;

use crate::support::ugo;
use glam::DVec3;
use std::path::{Path, PathBuf};
use ugo::directions::DirectionSet;
use ugo::geometry::{Mesh, Surface};
use ugo::luminaire::Source;
use ugo::render::{LitScene, Projection};
use ugo::scene::{Camera, Material};

/// A scene of `surfaces` whose field is their emission (nothing solved), seen with `sources`.
fn lit_scene(materials: Vec<Material>, surfaces: Vec<Surface>, sources: Vec<Source>) -> LitScene {
    let mesh = Mesh::build(&surfaces, 0.5);
    let luminance = mesh.emission.clone();
    let models = materials.iter().map(|m| m.model.clone()).collect();
    LitScene::new(mesh, DirectionSet::single(), luminance, models).with_luminaires(sources)
}

/// Per pixel of `camera`, the mean of `f` over the directions of its samples.
fn sample_mean(camera: &Camera, f: impl Fn(DVec3) -> f64) -> Vec<f64> {
    let view = Projection::of(camera);
    let mut means = Vec::with_capacity(view.width * view.height);
    for py in 0..view.height {
        for px in 0..view.width {
            let sum: f64 = (0..view.samples).map(|s| f(view.sample(px, py, s))).sum();
            means.push(sum / view.samples as f64);
        }
    }
    means
}

/// CIE 171's case 5.4 (an isotropic 10 000 lm lamp at (2, 1.5, 2) in a room) copied into
/// `dir` with its IES file and solved at 0.5 m patches: the case and the solution file.
fn solved_lamp_room(dir: &Path) -> (PathBuf, PathBuf) {
    for name in ["5.4-flux-conservation.toml", "isotropic-10000lm.ies"] {
        std::fs::copy(Path::new("cases/cie171").join(name), dir.join(name)).unwrap();
    }
    let (case, h5) = (dir.join("5.4-flux-conservation.toml"), dir.join("lit.h5"));
    let o = ugo(&["solve", case.to_str().unwrap(), "--patch-size", "0.5", "-o", h5.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    (case, h5)
}
