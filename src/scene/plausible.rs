//! Plausibility: values a valid case may hold but that are rarely meant, reported as
//! warnings (the work goes on) that name the table and the key like errors do: a
//! luminance brighter than the sun, a luminaire of a stadium's flux, a surface kilometres
//! long (a model in millimetres read as metres) or thinner than a hair, a reflectance no
//! paint reaches. Hard limits (overflow, NaN) are errors in `validate`.

use super::bounds::{bounds, shapes_bounds, surfaces_bounds};
use super::check::Context;
use super::description::Scene;
use super::error::SceneError;
use crate::geometry::{Emission, Shape};
use crate::luminaire::LuminaireKind;
use crate::material::MaterialModel;

/// The sun's disc, cd/m²: nothing in a lit scene is brighter.
const LUMINANCE: f64 = 1.6e9;
/// Flux of one surface or luminaire, lm (a large floodlight gives about 2e5 lm).
const FLUX: f64 = 1e7;
/// Illuminance of parallel light, lx (direct sunlight: at most about 1.2e5 lx).
const ILLUMINANCE: f64 = 1.5e5;
/// Lengths of one surface, m: beyond 1 km, or below 0.1 mm.
const LONGEST: f64 = 1e3;
const SHORTEST: f64 = 1e-4;
/// A mesh model (OBJ, glTF) this long, m, was probably drawn in millimetres or centimetres.
const MODEL_LONGEST: f64 = 500.0;
/// A mesh model (OBJ, glTF) this many times longer than the rest of the scene was probably drawn in
/// millimetres (a 450 mm chair read as 450 m in a 9 m room is 50 times the room).
const MODEL_TO_ROOM: f64 = 10.0;
/// Diffuse reflectance above this is laboratory material (white standards), not a room.
const REFLECTANCE: f64 = 0.98;

/// Every warning of `scene`, in the order of its tables.
pub fn warnings(scene: &Scene) -> Vec<SceneError> {
    let mut out = scene.file_warnings.clone();
    let path = &scene.path;
    let room = extent_of_all_but_models(scene);
    for (index, m) in scene.materials.iter().enumerate() {
        let at = Context::item(path, "material", &m.name, index);
        let (key, value) = match m.model {
            MaterialModel::Lambert { reflectance, transmittance } => {
                if reflectance + transmittance > REFLECTANCE && transmittance > 0.0 {
                    ("transmittance", reflectance + transmittance)
                } else {
                    ("reflectance", reflectance)
                }
            }
            MaterialModel::Phong { diffuse, specular, .. } | MaterialModel::Ggx { diffuse, specular, .. } => {
                ("specular", diffuse + specular)
            }
            MaterialModel::Mirror { reflectance } => ("reflectance", reflectance),
        };
        if value > REFLECTANCE && !matches!(m.model, MaterialModel::Mirror { .. }) {
            out.push(at.error(
                key,
                format!(
                    "reflects {value} of the light: above {REFLECTANCE}, only white standards do (paint: 0.9 at most)"
                ),
            ));
        }
    }
    for (index, s) in scene.surfaces.iter().enumerate() {
        let at = Context::item(path, "surface", &s.name, index);
        match s.emission {
            Some(Emission::Luminance(l)) if l > LUMINANCE => out.push(at.error(
                "emission.luminance",
                format!("{l:e} cd/m² is brighter than the sun's disc ({LUMINANCE:e} cd/m²)"),
            )),
            Some(Emission::Flux(f)) if f > FLUX => out
                .push(at.error("emission.flux", format!("{f:e} lm is more than a stadium's floodlight ({FLUX:e} lm)"))),
            _ => {}
        }
        let length = extent(&s.shape);
        let key = match s.shape {
            Shape::Disc { .. } | Shape::Sphere { .. } => "radius",
            Shape::Mesh { .. } => "scale",
            _ => "shape",
        };
        if let Shape::Mesh { .. } = s.shape
            && length > MODEL_LONGEST
        {
            out.push(at.error(key, format!("the model is {length:.4e} m across: {}", unit_hint(length))));
        } else if let Shape::Mesh { .. } = s.shape
            && room > 0.0
            && length > MODEL_TO_ROOM * room
        {
            let times = length / room;
            let what =
                format!("the model is {length:.4} m across, {times:.0} times the rest of the scene ({room:.4} m)");
            out.push(at.error(key, format!("{what}: {}", unit_hint(length))));
        } else if length > LONGEST {
            out.push(at.error(key, format!("{length:.4e} m across: lengths are in metres (1 km is {LONGEST:e} m)")));
        } else if length < SHORTEST {
            out.push(at.error(key, format!("{length:.4e} m across: lengths are in metres (0.1 mm is {SHORTEST:e} m)")));
        }
    }
    let (low, high) = surfaces_bounds(&scene.surfaces);
    let span = (high - low).length();
    if span > LONGEST && !out.iter().any(|w| w.message().contains("lengths are in metres")) {
        out.push(SceneError::new(
            path,
            "[[surface]]",
            "",
            format!(
                "the scene spans {span:.4e} m though no surface is longer than 1 km: lengths are in metres \
                 (drawn in millimetres, it would span {:.4} m)",
                span * 1e-3
            ),
        ));
    }
    for (index, l) in scene.luminaires.iter().enumerate() {
        let at = Context::item(path, "luminaire", &l.name, index);
        match &l.kind {
            LuminaireKind::Point(p) => {
                let flux = p.distribution.flux() * p.multiplier;
                if flux > FLUX {
                    let key = if p.file.is_some() { "file" } else { "flux" };
                    out.push(at.error(key, format!("{flux:e} lm is more than a stadium's floodlight ({FLUX:e} lm)")));
                }
            }
            LuminaireKind::Parallel { illuminance, .. } if *illuminance > ILLUMINANCE => out.push(at.error(
                "illuminance",
                format!("{illuminance:e} lx is more than direct sunlight gives (about 1.2e5 lx)"),
            )),
            LuminaireKind::Parallel { .. } | LuminaireKind::Window { .. } => {}
        }
    }
    out
}

/// What to do about a model `length` m across that was probably drawn in other units.
fn unit_hint(length: f64) -> String {
    format!(
        "lengths are in metres; a model drawn in millimetres needs scale = 0.001 ({:.4} m across), in \
         centimetres scale = 0.01 ({:.4} m)",
        length * 1e-3,
        length * 1e-2
    )
}

/// The diagonal of the bounding box of every surface but the mesh models, m (0 without any):
/// a model [`MODEL_TO_ROOM`] times longer was probably drawn in millimetres.
fn extent_of_all_but_models(scene: &Scene) -> f64 {
    let shapes = scene.surfaces.iter().map(|s| &s.shape).filter(|shape| !matches!(shape, Shape::Mesh { .. }));
    let (low, high) = shapes_bounds(shapes);
    if low.x <= high.x { (high - low).length() } else { 0.0 }
}

/// The diagonal of the bounding box of a shape's coarsest mesh, m.
fn extent(shape: &Shape) -> f64 {
    let b = bounds(shape);
    (b.1 - b.0).length()
}
