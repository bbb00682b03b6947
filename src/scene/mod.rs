//! The scene description: what a case file says, validated, in plain runtime types.
//!
//! Owns `docs/design.md` §7. The parser (`schema`) records exactly what the TOML file holds;
//! `validate` turns it into a [`Scene`] or a [`SceneError`] that names the file, the
//! table and the key. Nothing downstream (meshing, kernel, solvers) sees TOML.

mod arrays;
mod automatic;
mod bounds;
mod check;
mod description;
mod discretization;
mod discretization_keys;
mod error;
mod files;
mod glare_grid;
mod gltf;
mod gltf_texture;
mod gltf_topology;
mod gltf_uri;
mod grid;
mod holes;
mod instances;
mod light_scene;
mod loaded;
mod luminaire;
mod luminaire_array;
mod material;
mod mesh;
mod obj;
mod observer;
mod plausible;
mod polygon;
mod probe;
mod schema;
mod shape_keys;
mod sky;
mod surface;
mod validate;
mod window_place;
mod work_plane;

pub use automatic::{FINE_PATCH, UNIFORM_PAIRS, by_size};
pub use check::number;
pub use description::{Camera, Material, Scene, SolverSettings};
pub use discretization::{
    Asked, ChosenBySize, Discretization, Given, Hierarchical, KernelAsked, KernelKind, Origin, ROOTS, SizeReason,
};
pub use discretization_keys::OldSpelling;
pub use error::SceneError;
pub use files::{CaseFile, CaseFiles, regular_file};
pub use glare_grid::{GlareGrid, View};
pub use grid::{Grid, MapScale, MapStyle, Target};
pub use light_scene::{DEFAULT_GROUP, LightGroup, LightScene, Lighting};
pub use observer::Observer;
pub use probe::{Probe, ProbeKind};
pub use schema::RawCamera;
pub use sky::{DEFAULT_GROUND_REFLECTANCE, DEFAULT_HORIZONTAL_ILLUMINANCE};
pub use work_plane::{BORDER, en12464_spacing};

use std::path::Path;

impl Camera {
    /// A camera given outside a case file (e.g. on the command line, `source` says where),
    /// checked by the rules of a `[[camera]]` table.
    pub fn from_keys(keys: &RawCamera, source: &str) -> Result<Camera, SceneError> {
        validate::camera_from_keys(keys, source)
    }
}

impl Scene {
    /// Reads and validates a case file.
    pub fn load(path: &Path) -> Result<Scene, SceneError> {
        let cannot = |e: std::io::Error| SceneError::new(path, "", "", format!("cannot read the case file: {e}"));
        regular_file(path).map_err(cannot)?;
        let bytes = std::fs::read(path).map_err(cannot)?;
        let source = String::from_utf8(bytes).map_err(|e| {
            let at = e.utf8_error().valid_up_to();
            let bytes = e.as_bytes();
            let line = bytes[..at].iter().filter(|&&b| b == b'\n').count() + 1;
            let column = at - bytes[..at].iter().rposition(|&b| b == b'\n').map_or(0, |i| i + 1) + 1;
            let message = format!("line {line}: not UTF-8 text (byte 0x{:02x} at column {column})", bytes[at]);
            SceneError::new(path, "", "", message)
        })?;
        Scene::parse(path, source)
    }

    /// Validates case text as if read from `path` (OBJ paths are relative to its folder).
    pub fn parse(path: &Path, source: String) -> Result<Scene, SceneError> {
        Scene::parse_with(path, source, CaseFiles::disk())
    }

    /// [`Scene::parse`] reading the files the case names through `files` (a solution
    /// file's stored copies).
    pub fn parse_with(path: &Path, source: String, files: CaseFiles) -> Result<Scene, SceneError> {
        let raw = schema::parse(path, &source)?;
        validate::validate(path, source, raw, files)
    }

    /// Values that are valid but rarely meant (brighter than the sun, a model in
    /// millimetres read as metres, …): each names its table and key; the caller reports
    /// them (`ugo: warning: …`) and goes on.
    pub fn warnings(&self) -> Vec<SceneError> {
        plausible::warnings(self)
    }

    /// The case's discretization with the command line's `flags` in place of its keys,
    /// checked by the same rules (the kernel chosen by size again if it was left to it).
    pub fn discretize(&mut self, flags: &Asked) -> Result<(), SceneError> {
        let asked = self.asked.overridden_by(flags);
        let (surfaces, before) = (&self.surfaces, &self.discretization);
        // the pairs forecast depends on the patch size only: a choice made at it stands
        let choose = |h, directions| match before.chosen_by_size {
            Some(chosen) if chosen.patch_size == h => (before.kernel, chosen),
            _ => by_size(h, directions, surfaces, &self.materials),
        };
        self.discretization = asked.resolve(&self.path, choose)?;
        self.asked = asked;
        Ok(())
    }

    /// Looks a surface up by name.
    pub fn surface_index(&self, name: &str) -> Option<usize> {
        self.surfaces.iter().position(|s| s.name == name)
    }
}
