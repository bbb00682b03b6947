//! The discretized problem of a scene: mesh, visibility, kernel `K = B·G` and source
//! `L0` (`docs/design.md` §6, the arrows from Scene to Kernel): the surfaces' own emission plus
//! the luminaires' direct light reflected once, `L0 = L_e + B·D` (`crate::luminaire`).
//! The kernel is explicit (`explicit.rs`, every facing pair of patches) or hierarchical
//! (`hierarchical.rs`, `docs/design.md` §3b: links between elements at the levels its oracle
//! accepts, refined with the solve); either way the mesh is the unknowns' patches.
//!
//! The kernel's memory is estimated before assembly (after each refinement pass for the
//! hierarchy) and a kernel over the limit is refused with the estimate and the ways out.
//! A saved explicit `G` is reused instead of assembled (`reuse.rs`) when the case's
//! fingerprint (`fingerprint.rs`) matches the one stored with it.

mod explicit;
mod fingerprint;
mod group;
mod hierarchical;
mod range;
mod reuse;
mod source;
mod system;

pub use fingerprint::{Change, Fingerprint, KERNEL_FORMAT, Part, Stamp};
pub use range::{OutOfRange, check_transport, locate, place};
pub use reuse::{NotThisMesh, StoredParts};
pub use source::SourceTerm;
pub use system::{AssemblyStats, HierarchyRecord, Model, ModelError, ModelOptions, Refinement};

use crate::geometry::Mesh;
use crate::kernel::Forecast;
use crate::progress::Progress;
use crate::scene::{Assembly, Scene};
use source::source_term;

impl Model {
    /// Meshes the scene only (for estimates).
    pub fn mesh(scene: &Scene, options: &ModelOptions) -> Mesh {
        Mesh::build(&scene.surfaces, options.patch_size)
    }

    /// What the model of `scene` will cost, from its surfaces, before meshing.
    pub fn forecast(scene: &Scene, options: &ModelOptions) -> Forecast {
        let (surfaces, materials) = (&scene.surfaces, scene.materials.len());
        match scene.discretization.assembly {
            Assembly::Explicit => Forecast::explicit(surfaces, materials, options.patch_size, &options.directions),
            Assembly::Hierarchical { smallest, .. } => {
                Forecast::hierarchical(surfaces, materials, options.patch_size, smallest, &options.directions)
            }
        }
    }

    /// Builds the full model with the scene's assembly (`[discretization] method`), after
    /// its forecast is checked against the memory limit; `progress` hears of the pair
    /// evaluations, or of the hierarchy's refinement passes.
    pub fn build(scene: &Scene, options: &ModelOptions, progress: &dyn Progress) -> Result<Model, ModelError> {
        Model::forecast(scene, options).check(options.memory_limit)?;
        match scene.discretization.assembly {
            Assembly::Explicit => explicit::build(scene, options, progress),
            Assembly::Hierarchical { tolerance, smallest } => {
                hierarchical::build(scene, options, Refinement { tolerance, smallest }, progress)
            }
        }
    }

    /// `L0` again, after the material blocks of the kernel changed.
    pub fn source_term(&self) -> Vec<f64> {
        source_term(&self.kernel.blocks, &self.mesh, &self.direct, self.kernel.cells())
    }
}
