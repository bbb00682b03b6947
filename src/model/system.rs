//! The discretized system `x = L0 + K x` of a scene (`docs/design.md` §6): the model's parts
//! (mesh, ray caster, kernel, source term, luminaires), how it is discretized, what its
//! assembly cost, and why none was built.

use super::range::OutOfRange;
use crate::geometry::Mesh;
use crate::interrupt::Interrupted;
use crate::kernel::hierarchy::{Census, Pass, Stopped, Structure};
use crate::kernel::{BalanceReport, Kernel, TooLarge};
use crate::luminaire::{DirectLight, Source};
use crate::material::MaterialModel;
use crate::scene::Hierarchical;
use crate::solve::SolveError;
use crate::transfer::image::PlaneMirror;
use crate::visibility::{Faces, Visibility};
use thiserror::Error;

/// Why no model was built.
#[derive(Debug, Error)]
pub enum ModelError {
    /// Over the memory limit: the model's forecast before meshing, its count on the mesh,
    /// or the hierarchy's links after a pass.
    #[error(transparent)]
    TooLarge(#[from] TooLarge),
    /// A value of the source term or the kernel that no solve can carry.
    #[error(transparent)]
    OutOfRange(#[from] OutOfRange),
    /// A signal asked the process to stop.
    #[error(transparent)]
    Interrupted(#[from] Interrupted),
    /// A solve between the hierarchy's refinement passes failed.
    #[error("refining the hierarchical kernel: {0}")]
    Refinement(#[from] SolveError),
    /// Part files that do not make this case's tree (`part_rows`).
    #[error("the part files: {0}")]
    Parts(String),
}

impl From<Stopped> for ModelError {
    fn from(stopped: Stopped) -> Self {
        match stopped {
            Stopped::Interrupted(i) => ModelError::Interrupted(i),
            Stopped::TooLarge(t) => ModelError::TooLarge(t),
        }
    }
}

/// Timings and counts of the assembly.
#[derive(Debug, Clone)]
pub struct AssemblyStats {
    /// Time spent meshing, s.
    pub mesh_seconds: f64,
    /// Time spent building the ray caster, s.
    pub bvh_seconds: f64,
    /// The kernel: the uniform assembly, or every refinement pass and its solve.
    pub kernel_seconds: f64,
    /// Time spent on the luminaires' direct light.
    pub light_seconds: f64,
    /// Patch pairs integrated (uniform), or links (hierarchical).
    pub pairs: usize,
    /// Occlusion rays traced, the luminaires' included.
    pub rays: usize,
    /// How balancing changed the uniform kernel's `G` (the hierarchy balances in its passes, `HierarchyRecord`).
    pub balance: Option<BalanceReport>,
}

/// A scene discretized into the linear system `x = L0 + K x`.
pub struct Model {
    /// The unknowns' patches: the uniform mesh, or the hierarchy's leaves.
    pub mesh: Mesh,
    /// The ray caster over the mesh's faces.
    pub visibility: Visibility,
    /// The patches of each face, for probes and grids.
    pub faces: Faces,
    /// The kernel `K = B·G`.
    pub kernel: Kernel,
    /// The scene's materials by index, whose own luminance factors the readouts of
    /// glossy surfaces apply (the kernel holds their cell blocks).
    pub materials: Vec<MaterialModel>,
    /// Source term `L0(i,k)`, flat, `x[i·K + k]`.
    pub l0: Vec<f64>,
    /// The luminaires, placed.
    pub sources: Vec<Source>,
    /// Their direct light on every (patch, cell), by way of `mirrors` included.
    pub direct: DirectLight,
    /// The plane mirrors whose light the kernel carries by images (`transfer::image`); none
    /// for the hierarchical kernel, whose mirrors reflect cell to cell.
    pub mirrors: Vec<PlaneMirror>,
    /// Timings and counts of the build.
    pub stats: AssemblyStats,
    /// What the hierarchical kernel made; `None` for the uniform one.
    pub hierarchy: Option<HierarchyRecord>,
}

/// What the hierarchical kernel made.
#[derive(Debug, Clone, PartialEq)]
pub struct HierarchyRecord {
    /// Its roots and link tolerance.
    pub parameters: Hierarchical,
    /// The edge its leaves could split down to, m.
    pub patch_size: f64,
    /// Root elements (patches of the roots' mesh).
    pub roots: usize,
    /// One record per refinement pass.
    pub history: Vec<Pass>,
    /// What the final hierarchy is made of.
    pub census: Census,
    /// The tree's skeleton and links, kept for a kernel file (`Model::build_to_save`, or
    /// read from one); `None` otherwise.
    pub structure: Option<Structure>,
}
