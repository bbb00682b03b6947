//! The runtime scene: what a validated case file says, in plain types (`docs/design.md` §7).

use super::files::CaseFile;
use super::grid::Grid;
use super::light_scene::Lighting;
use super::probe::Probe;
use crate::directions::Scheme;
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
    /// `[discretization]`: patch size, direction cells, kernel.
    pub discretization: Discretization,
    /// `[solver]`: method and stopping rule.
    pub solver: SolverSettings,
    /// The `[[material]]` tables, in file order.
    pub materials: Vec<Material>,
    /// The `[[surface]]` tables, in file order (an OBJ mesh one surface per material).
    pub surfaces: Vec<Surface>,
    /// The `[[probe]]` tables, in file order.
    pub probes: Vec<Probe>,
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
    /// Every file the case names (OBJ, photometric), as read.
    pub files: Vec<CaseFile>,
}

/// `[discretization]`: how finely surfaces are meshed.
#[derive(Debug, Clone, PartialEq)]
pub struct Discretization {
    /// Target edge length of the patches, m; for the hierarchical kernel, of its roots
    /// (the largest elements).
    pub patch_size: f64,
    /// Direction set (default one cell: radiosity).
    pub directions: Scheme,
    /// How the kernel is built (`method`; without it, chosen by size: [`Automatic`]).
    pub assembly: Assembly,
    /// Set when `method` was not given (or is `"auto"`): what the choice was made from.
    pub automatic: Option<Automatic>,
}

/// Why the kernel was chosen by size (`scene/automatic.rs`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Automatic {
    /// The case's `patch_size`, m: the explicit kernel's patches, or the hierarchy's
    /// smallest elements.
    pub asked: f64,
    /// Unordered pairs of facing patches the explicit kernel would have at `asked`.
    pub facing_pairs: f64,
}

/// `[discretization] method`: how the kernel `K` is built.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Assembly {
    /// Every facing pair of patches gets its entry (`docs/design.md` §3).
    Explicit,
    /// Element trees over patches of `patch_size`, links where the oracle accepts them
    /// (`docs/design.md` §3b): `tolerance` is the error allowed per link relative to the mean
    /// reflected luminance, `smallest` the smallest element edge, m.
    Hierarchical {
        /// Error allowed per link relative to the mean reflected luminance.
        tolerance: f64,
        /// Smallest element edge, m.
        smallest: f64,
    },
}

impl Assembly {
    /// The names of `method`.
    pub const NAMES: &'static str = "\"explicit\", \"hierarchical\" or \"auto\"";

    /// The hierarchical kernel with its default tolerance and smallest element.
    pub fn hierarchical() -> Assembly {
        let defaults = crate::kernel::hierarchy::Options::default();
        Assembly::Hierarchical { tolerance: defaults.tolerance, smallest: defaults.smallest }
    }

    /// `"explicit"` or `"hierarchical"`, as `method` names it.
    pub fn name(&self) -> &'static str {
        match self {
            Assembly::Explicit => "explicit",
            Assembly::Hierarchical { .. } => "hierarchical",
        }
    }
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
