//! The scene description: what a case file says, validated, in plain runtime types.
//!
//! Owns `design.md` §7. The parser (`schema`) records exactly what the TOML file holds;
//! `validate` turns it into a [`Scene`] or a [`SceneError`] that names the file, the
//! table and the key. Nothing downstream (meshing, kernel, solvers) sees TOML.

mod error;
mod grid;
mod luminaire;
mod schema;
mod validate;

pub use error::SceneError;
pub use grid::Grid;
pub use luminaire::{Luminaire, LuminaireKind, PointLuminaire};
pub use schema::RawCamera;

use glam::DVec3;
use std::path::{Path, PathBuf};

/// A validated scene, ready for meshing.
#[derive(Debug, Clone)]
pub struct Scene {
    /// The case file this scene was read from.
    pub path: PathBuf,
    /// The case file's text, stored verbatim in every output file.
    pub source: String,
    pub name: String,
    pub description: String,
    pub discretization: Discretization,
    pub solver: SolverSettings,
    pub materials: Vec<Material>,
    pub surfaces: Vec<Surface>,
    pub probes: Vec<Probe>,
    pub cameras: Vec<Camera>,
    pub grids: Vec<Grid>,
    pub luminaires: Vec<Luminaire>,
}

/// `[discretization]`: how finely surfaces are meshed.
#[derive(Debug, Clone, PartialEq)]
pub struct Discretization {
    /// Target edge length of the patches, m.
    pub patch_size: f64,
    /// Direction set: a cell count (`"64"`), `"klems"` or `"tregenza"` (default `"1"`).
    pub directions: String,
}

/// `[solver]`: the method and its stopping rule.
#[derive(Debug, Clone, PartialEq)]
pub struct SolverSettings {
    /// A name `solve::Method::parse` accepts (default `"neumann"`).
    pub method: String,
    /// Relative residual `‖L0 + Kx − x‖₂/‖L0‖₂` at which the iteration stops.
    pub tolerance: f64,
    /// The iteration gives up (with an error) after this many kernel applications.
    pub max_iterations: usize,
}

impl Default for SolverSettings {
    fn default() -> Self {
        SolverSettings { method: "neumann".into(), tolerance: 1e-8, max_iterations: 10_000 }
    }
}

/// `[[material]]`: a named luminance-factor model (`design.md` §1).
#[derive(Debug, Clone, PartialEq)]
pub struct Material {
    pub name: String,
    pub model: MaterialModel,
}

/// The closed set of material models, as luminance factors `ρ = π f_r` (`design.md` §1).
#[derive(Debug, Clone, PartialEq)]
pub enum MaterialModel {
    /// Ideal diffuse reflector and (on a two-sided surface) diffuse transmitter:
    /// `ρ ≡ reflectance` on the incident side, `τ ≡ transmittance` on the other;
    /// `reflectance + transmittance ≤ 1`.
    Lambert { reflectance: f64, transmittance: f64 },
    /// Normalized modified Phong (Lafortune & Willems 1994):
    /// `ρ = diffuse + specular · (n + 2)/2 · cosⁿα`, `α` between the outgoing direction
    /// and the mirror image of the incoming one; `diffuse + specular ≤ 1`.
    Phong { diffuse: f64, specular: f64, exponent: f64 },
    /// Ideal specular reflector of reflectance `reflectance`.
    Mirror { reflectance: f64 },
    /// GGX (Trowbridge–Reitz) microfacet reflection with the height-correlated Smith
    /// masking-shadowing term and no Fresnel factor, plus a diffuse part:
    /// `ρ = diffuse + specular · π D(h) G₂ / (4 cosθ cosθ')`, width `roughness` (α).
    Ggx { diffuse: f64, specular: f64, roughness: f64 },
}

/// Lambertian self-emission of a surface.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Emission {
    /// Luminance, cd/m², the same at every point and in every direction.
    Luminance(f64),
    /// Total luminous flux of the surface, lm, spread uniformly over its (meshed) area.
    Flux(f64),
}

/// `[[surface]]`: one named piece of geometry with its material.
#[derive(Debug, Clone)]
pub struct Surface {
    pub name: String,
    pub shape: Shape,
    /// Index into [`Scene::materials`].
    pub material: usize,
    /// Both sides reflect (and emit): meshed as two patches per element, back to back.
    pub two_sided: bool,
    /// Normals are flipped (a room seen from inside).
    pub inside: bool,
    pub emission: Option<Emission>,
}

/// The closed set of shapes. Lengths in metres, angles in degrees.
#[derive(Debug, Clone, PartialEq)]
pub enum Shape {
    /// Parallelogram `origin + s·edge_u + t·edge_v`, `s, t ∈ [0,1]`; normal `u × v`.
    Rectangle { origin: DVec3, edge_u: DVec3, edge_v: DVec3 },
    /// Planar simple polygon, vertices counter-clockwise seen from the front.
    Polygon { vertices: Vec<DVec3> },
    /// Axis-aligned box rotated about the vertical (y) axis through its centre; normals outward.
    Box { min: DVec3, max: DVec3, rotate_y_deg: f64 },
    /// Flat disc facing `normal`.
    Disc { center: DVec3, normal: DVec3, radius: f64 },
    /// Sphere with outward normals (tessellated into planar patches).
    Sphere { center: DVec3, radius: f64 },
    /// Triangles loaded from an OBJ file (already scaled and translated), normals by winding.
    Mesh { file: PathBuf, triangles: Vec<[DVec3; 3]> },
}

/// `[[probe]]`: a point sensor of luminance (cd/m²) and illuminance (lx).
#[derive(Debug, Clone, PartialEq)]
pub struct Probe {
    pub name: String,
    pub position: DVec3,
    /// Unit normal of the sensor's receiving side.
    pub normal: DVec3,
}

/// `[[camera]]`: a pinhole camera for `ugo render`.
#[derive(Debug, Clone, PartialEq)]
pub struct Camera {
    pub name: String,
    pub position: DVec3,
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
        let source = std::fs::read_to_string(path)
            .map_err(|e| SceneError::new(path, "", "", format!("cannot read the case file: {e}")))?;
        Scene::parse(path, source)
    }

    /// Validates case text as if read from `path` (OBJ paths are relative to its folder).
    pub fn parse(path: &Path, source: String) -> Result<Scene, SceneError> {
        let raw = schema::parse(path, &source)?;
        validate::validate(path, source, raw)
    }

    /// Looks a surface up by name.
    pub fn surface_index(&self, name: &str) -> Option<usize> {
        self.surfaces.iter().position(|s| s.name == name)
    }
}
