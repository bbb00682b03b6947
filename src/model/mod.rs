//! The discretized problem of a scene: mesh, visibility, kernel `K = B·G` and source
//! `L0` (`docs/design.md` §6, the arrows from Scene to Kernel): the surfaces' own emission plus
//! the luminaires' direct light reflected once, `L0 = L_e + B·D` (`crate::luminaire`).
//! The kernel is uniform (`uniform.rs`, every facing pair of patches) or hierarchical
//! (`hierarchical.rs`, `docs/design.md` §3b: links between elements at the levels its oracle
//! accepts, refined with the solve); either way the mesh is the unknowns' patches.
//!
//! The kernel's memory is estimated before assembly (after each refinement pass for the
//! hierarchy) and a kernel over the limit is refused with the estimate and the ways out.
//! A saved uniform `G` is reused instead of assembled (`reuse.rs`) when the case's
//! fingerprint (`fingerprint.rs`) matches the one stored with it.

mod fingerprint;
mod group;
mod hierarchical;
mod part;
mod part_join;
mod part_rows;
mod range;
mod readers;
mod reuse;
mod source;
mod system;
mod uniform;

pub use fingerprint::{Change, Fingerprint, KERNEL_FORMAT, Part, Stamp};
pub use part::{PartLink, PartLinks, link_part};
pub use part_join::{NamedPart, Unjoinable, join};
pub use part_rows::{PartRows, part_rows};
pub use range::{OutOfRange, check_transport, locate, place};
pub use reuse::{NotThisMesh, StoredHierarchy, StoredParts};
pub use source::SourceTerm;
pub use system::{AssemblyStats, HierarchyRecord, Model, ModelError};

use crate::geometry::Mesh;
use crate::kernel::Forecast;
use crate::progress::Progress;
use crate::scene::{KernelKind, Scene};
use source::source_term;

impl Model {
    /// The mesh the kernel starts from, for estimates: the uniform kernel's patches, or the
    /// hierarchy's roots.
    pub fn starting_mesh(scene: &Scene) -> Mesh {
        let d = &scene.discretization;
        match d.kernel {
            KernelKind::Uniform => Mesh::build(&scene.surfaces, d.patch_size),
            KernelKind::Hierarchical(h) => Mesh::build(&scene.surfaces, h.root_size),
        }
    }

    /// What the model of `scene` will cost, from its surfaces, before meshing.
    pub fn forecast(scene: &Scene) -> Forecast {
        let (surfaces, materials, d) = (&scene.surfaces, scene.materials.len(), &scene.discretization);
        let directions = d.directions.set();
        match d.kernel {
            KernelKind::Uniform => Forecast::uniform(surfaces, materials, d.patch_size, &directions),
            KernelKind::Hierarchical(h) => {
                Forecast::hierarchical(surfaces, materials, h.root_size, d.patch_size, &directions)
            }
        }
    }

    /// Builds the full model with the scene's kernel (`[discretization] kernel`), after
    /// its forecast is checked against the memory limit; `progress` hears of the pair
    /// evaluations, or of the hierarchy's refinement passes.
    pub fn build(scene: &Scene, progress: &dyn Progress) -> Result<Model, ModelError> {
        Model::build_keeping(scene, progress, false)
    }

    /// [`Model::build`], keeping what a kernel file stores of a hierarchy besides its
    /// operator: the tree's skeleton and the links (`HierarchyRecord::structure`).
    pub fn build_to_save(scene: &Scene, progress: &dyn Progress) -> Result<Model, ModelError> {
        Model::build_keeping(scene, progress, true)
    }

    fn build_keeping(scene: &Scene, progress: &dyn Progress, keep: bool) -> Result<Model, ModelError> {
        Model::forecast(scene).check(scene.discretization.memory_limit)?;
        match scene.discretization.kernel {
            KernelKind::Uniform => uniform::build(scene, progress),
            KernelKind::Hierarchical(h) => hierarchical::build(scene, h, progress, keep),
        }
    }

    /// `L0` again, after the material blocks of the kernel changed.
    pub fn source_term(&self) -> Vec<f64> {
        source_term(&self.kernel.blocks, &self.mesh, &self.direct, self.kernel.cells())
    }
}
