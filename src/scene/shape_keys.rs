//! What every shape builder of a `[[surface]]` reads: the table's context, the case's
//! files and materials ([`ShapeKeys`]), and what it returns: the surface's parts, each a
//! shape with its material when not the surface's own ([`Part`]; only a `mesh` whose
//! file's groups take materials has more than one, `mesh.rs`).

use super::check::Context;
use super::description::Material;
use super::error::SceneError;
use super::files::CaseFiles;
use crate::geometry::Shape;
use glam::DVec3;
use std::cell::RefCell;

/// Reads the keys of one shape, reporting missing required ones.
#[derive(Clone, Copy)]
pub(super) struct ShapeKeys<'a> {
    pub at: &'a Context<'a>,
    pub shape: &'a str,
    /// Where a `mesh` reads its file.
    pub files: &'a CaseFiles,
    /// The case's materials, which a mesh file's groups are mapped to, and those made from
    /// its colours (`mesh.rs`).
    pub materials: &'a RefCell<Vec<Material>>,
    /// What the mesh files hold that ugo does not read.
    pub warnings: &'a RefCell<Vec<SceneError>>,
    /// The case text, for the line of a value.
    pub source: &'a str,
}

impl ShapeKeys<'_> {
    pub(super) fn required<T>(&self, key: &str, value: Option<T>) -> Result<T, SceneError> {
        let message = || format!("missing: shape \"{}\" needs `{key}`", self.shape);
        value.ok_or_else(|| self.at.error(key, message()))
    }

    pub(super) fn point(&self, key: &str, value: Option<[f64; 3]>) -> Result<DVec3, SceneError> {
        self.at.place(key, self.required(key, value)?)
    }

    pub(super) fn radius(&self, value: Option<f64>) -> Result<f64, SceneError> {
        self.at.length("radius", self.required("radius", value)?)
    }
}

/// A shape of a surface, and its material when not the surface's `material`.
pub(super) struct Part {
    pub shape: Shape,
    pub material: Option<usize>,
}

/// A shape of the surface's own material.
pub(super) fn whole(shape: Shape) -> Vec<Part> {
    vec![Part { shape, material: None }]
}

/// The index of the material named `name` (the value of `key`).
pub(super) fn material_index(at: &Context, key: &str, name: &str, materials: &[Material]) -> Result<usize, SceneError> {
    materials.iter().position(|m| m.name == name).ok_or_else(|| {
        let known: Vec<String> = materials.iter().map(|m| format!("\"{}\"", m.name)).collect();
        at.error(key, format!("unknown material \"{name}\"; known: {}", known.join(", ")))
    })
}
