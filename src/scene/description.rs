//! The runtime scene: what a validated case file says, in plain types (`docs/design.md` §7).

use super::discretization::{Asked, Discretization};
use super::discretization_keys::OldSpelling;
use super::files::CaseFile;
use super::glare_grid::GlareGrid;
use super::grid::Grid;
use super::light_scene::Lighting;
use super::observer::Observer;
use super::probe::Probe;
use crate::geometry::Surface;
use crate::luminaire::Luminaire;
use crate::material::MaterialModel;
use crate::sky::Sky;
use crate::solve::Method;
use glam::DVec3;
use std::path::PathBuf;

/// A validated scene, ready for meshing.
#[derive(Debug, Clone)]
pub struct Scene {
    /// The case file this scene was read from.
    pub path: PathBuf,
    /// The case file's text, stored verbatim in every output file.
    pub source: String,
    /// `[scene] name` (default: the case file's stem).
    pub name: String,
    /// `[scene] description` (default empty).
    pub description: String,
    /// What `[discretization]` asks for, kept so that the command line's flags can be
    /// resolved with it (`Scene::discretize`).
    pub asked: Asked,
    /// `[discretization]` resolved: the one record of how the case is discretized.
    pub discretization: Discretization,
    /// The `[discretization]` keys read in their old spelling, to be told.
    pub old_spelling: Vec<OldSpelling>,
    /// `[solver]`: method and stopping rule.
    pub solver: SolverSettings,
    /// The `[[material]]` tables, in file order, then those made from the base colours of
    /// glTF meshes (`FILE:name`).
    pub materials: Vec<Material>,
    /// What the mesh files hold that ugo does not read (a texture, an emissive factor,
    /// lines or points), told among [`Scene::warnings`](crate::scene::Scene::warnings).
    pub file_warnings: Vec<super::error::SceneError>,
    /// The `[[surface]]` tables, in file order (a mesh one surface per material).
    pub surfaces: Vec<Surface>,
    /// The `[[probe]]` tables, in file order.
    pub probes: Vec<Probe>,
    /// The `[[observer]]` tables, in file order: where the UGR is read.
    pub observers: Vec<Observer>,
    /// The `[[glare_grid]]` tables, in file order: the UGR on grids of eye positions.
    pub glare_grids: Vec<GlareGrid>,
    /// The `[[camera]]` tables, in file order.
    pub cameras: Vec<Camera>,
    /// The `[[grid]]` tables, in file order.
    pub grids: Vec<Grid>,
    /// The `[[luminaire]]` tables, then one per `[[window]]`, then the `[sky]`'s sun.
    pub luminaires: Vec<Luminaire>,
    /// `[sky]`: the sky, sun and ground outside the openings.
    pub sky: Option<Sky>,
    /// The sources' groups, the light scenes and the maintenance factor (already applied).
    pub lighting: Lighting,
    /// Every file the case names (OBJ, glTF and its buffers, photometric), as read.
    pub files: Vec<CaseFile>,
}

/// `[solver]`: the method and its stopping rule.
#[derive(Debug, Clone, PartialEq)]
pub struct SolverSettings {
    /// Default successive approximation (Neumann).
    pub method: Method,
    /// Relative residual `‖L0 + Kx − x‖₂/‖L0‖₂` at which the iteration stops.
    pub tolerance: f64,
    /// The iteration gives up (with an error) after this many kernel applications.
    pub max_iterations: usize,
}

impl Default for SolverSettings {
    fn default() -> Self {
        SolverSettings { method: Method::Neumann, tolerance: 1e-8, max_iterations: 10_000 }
    }
}

/// `[[material]]`: a named luminance-factor model (`docs/design.md` §1).
#[derive(Debug, Clone, PartialEq)]
pub struct Material {
    /// The material's name, unique in the scene.
    pub name: String,
    /// Its luminance-factor model and parameters.
    pub model: MaterialModel,
}

/// `[[camera]]`: a pinhole camera for `ugo render`.
#[derive(Debug, Clone, PartialEq)]
pub struct Camera {
    /// The camera's name, unique in the scene.
    pub name: String,
    /// The eye (centre of projection), m.
    pub position: DVec3,
    /// The point the camera looks at, m.
    pub look_at: DVec3,
    /// Unit vector giving the image's upward direction (not parallel to the view).
    pub up: DVec3,
    /// Vertical field of view, degrees, in (0, 180).
    pub fov_deg: f64,
    /// Image width and height, pixels.
    pub resolution: [usize; 2],
    /// Primary rays per pixel (stratified).
    pub samples: usize,
}
