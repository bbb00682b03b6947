//! The model around a stored kernel (issue 15 and issue 36, `docs/kernel-file.md`): `G` as
//! read from a kernel file instead of assembled or refined, the blocks `B` and the
//! luminaires' direct light `D` as stored or, when only they changed, rebuilt from the
//! case, and `L0 = L_e + B·D` (`docs/design.md` §2, §3). The uniform kernel's mesh, its ray
//! caster and its patches' exposed areas are rebuilt from the case (cheap); a hierarchy's leaves are the file's
//! (`StoredHierarchy`), with the case's materials and emission, and their ray caster is
//! built on them as after a refinement.

use super::source::source_term;
use super::system::{AssemblyStats, HierarchyRecord, Model};
use super::uniform::mirrors_of;
use crate::geometry::{Mesh, Patch};
use crate::kernel::hierarchy::{Census, Structure};
use crate::kernel::{Kernel, Transport};
use crate::luminaire::{DirectLight, Source, direct_light};
use crate::material::Block;
use crate::progress::Silent;
use crate::scene::{Hierarchical, KernelKind, Scene};
use crate::transfer::exposure::measure_exposure;
use crate::visibility::{Faces, Visibility};
use std::time::Instant;
use thiserror::Error;

/// What a kernel file supplies to the model.
pub struct StoredParts {
    /// The stored transport `G`: the uniform kernel's matrix or the hierarchy's operator.
    pub g: Transport,
    /// The stored blocks, or `None` to build them from the case.
    pub blocks: Option<Vec<Block>>,
    /// The stored direct light, or `None` to trace it for the case's luminaires.
    pub direct: Option<DirectLight>,
    /// What a hierarchical kernel stores besides its operator; `None` for the uniform one.
    pub hierarchy: Option<StoredHierarchy>,
    /// Seconds spent reading them.
    pub read_seconds: f64,
}

/// What a kernel file holds of a hierarchy besides its operator.
#[derive(Debug, Clone)]
pub struct StoredHierarchy {
    /// The leaves as saved, in unknown order (their materials and emission are the case's).
    pub leaves: Vec<Patch>,
    /// Per leaf, the flux below which a shadow edge of the luminaires' light was not cut
    /// further (`DirectLight::least`), lm: the cuts of a new `D` and of light scenes.
    pub least: Vec<f64>,
    /// Root elements the hierarchy grew from.
    pub roots: usize,
    /// The tree's skeleton and links.
    pub structure: Structure,
}

/// A stored kernel that does not fit the case's mesh.
#[derive(Debug, Error)]
pub enum NotThisMesh {
    /// `G`'s size is not the case's unknowns.
    #[error(
        "the stored G has {rows} rows, but the case meshes into {patches} patches × {cells} cells = {} unknowns",
        patches * cells
    )]
    Size {
        /// Rows of the stored `G`.
        rows: usize,
        /// Patches of the case's mesh (or of the stored leaves).
        patches: usize,
        /// Direction cells per patch of the case.
        cells: usize,
    },
    /// The file holds the other kernel than the case's (uniform or hierarchical).
    #[error("the file holds the {file} kernel, the case asks for the {case} one")]
    Kind {
        /// The file's kernel.
        file: &'static str,
        /// The case's kernel.
        case: &'static str,
    },
    /// A stored leaf lies on a surface the case does not have.
    #[error("the stored leaf {leaf} lies on surface {surface}, but the case has {surfaces} surfaces")]
    Surface {
        /// The leaf.
        leaf: usize,
        /// Its surface index.
        surface: u32,
        /// Surfaces of the case.
        surfaces: usize,
    },
}

impl Model {
    /// The model of `scene` around the stored parts: nothing is assembled or refined.
    pub fn with_kernel(scene: &Scene, stored: StoredParts) -> Result<Model, NotThisMesh> {
        let t = Instant::now();
        let hierarchical = match scene.discretization.kernel {
            KernelKind::Hierarchical(h) => Some(h),
            KernelKind::Uniform => None,
        };
        let mut mesh = match (&stored.hierarchy, hierarchical) {
            (Some(h), Some(parameters)) => leaf_mesh(scene, parameters.root_size, &h.leaves)?,
            (None, None) => Mesh::build(&scene.surfaces, scene.discretization.patch_size),
            (Some(_), None) => return Err(NotThisMesh::Kind { file: "hierarchical", case: "uniform" }),
            (None, Some(_)) => return Err(NotThisMesh::Kind { file: "uniform", case: "hierarchical" }),
        };
        let directions = scene.discretization.directions.set();
        let (rows, patches, cells) = (stored.g.rows(), mesh.len(), directions.len());
        if rows != patches * cells {
            return Err(NotThisMesh::Size { rows, patches, cells });
        }
        let mesh_seconds = t.elapsed().as_secs_f64();
        let t = Instant::now();
        let visibility = Visibility::build_for(&scene.surfaces, &mesh);
        if stored.hierarchy.is_none() {
            // the uniform mesh's exposed areas, as `uniform::build` measures them (the
            // hierarchy's leaves keep the file's)
            measure_exposure(&mut mesh, &visibility, &Silent);
        }
        let bvh_seconds = t.elapsed().as_secs_f64();
        let blocks =
            stored.blocks.unwrap_or_else(|| scene.materials.iter().map(|m| m.model.block(&directions)).collect());
        let record = stored.hierarchy.zip(hierarchical).map(|(h, parameters)| record(scene, parameters, h, &stored.g));
        let kernel = Kernel::on_mesh(stored.g, &mesh, directions, blocks);
        let t = Instant::now();
        let sources: Vec<Source> = scene.luminaires.iter().map(Source::of).collect();
        // the hierarchy's mirrors reflect cell to cell (no images)
        let mirrors = if record.is_some() { Vec::new() } else { mirrors_of(scene, &mesh) };
        let least = record.as_ref().map_or(&[][..], |(_, least)| least.as_slice());
        let direct = stored
            .direct
            .unwrap_or_else(|| direct_light(&sources, &mesh, &visibility, &kernel.directions, least, &mirrors));
        let stats = AssemblyStats {
            mesh_seconds,
            bvh_seconds,
            kernel_seconds: stored.read_seconds,
            light_seconds: t.elapsed().as_secs_f64(),
            pairs: kernel.g.hierarchy().map_or(0, |g| g.links()),
            rays: direct.rays,
            balance: None,
        };
        let l0 = source_term(&kernel.blocks, &mesh, &direct, kernel.cells());
        let faces = Faces::of(&mesh);
        let materials = scene.materials.iter().map(|m| m.model.clone()).collect();
        let hierarchy = record.map(|(r, _)| r);
        Ok(Model { mesh, visibility, faces, kernel, materials, l0, sources, direct, mirrors, stats, hierarchy })
    }
}

/// The stored leaves as a mesh with the case's materials and emission (each surface's, as
/// the roots' mesh gives it).
fn leaf_mesh(scene: &Scene, root_size: f64, leaves: &[Patch]) -> Result<Mesh, NotThisMesh> {
    let surfaces = scene.surfaces.len();
    if let Some((leaf, p)) = leaves.iter().enumerate().find(|(_, p)| p.surface as usize >= surfaces) {
        return Err(NotThisMesh::Surface { leaf, surface: p.surface, surfaces });
    }
    let roots = Mesh::build(&scene.surfaces, root_size);
    let mut luminance = vec![0.0; surfaces];
    roots.patches.iter().zip(&roots.emission).for_each(|(p, &e)| luminance[p.surface as usize] = e);
    let patches: Vec<Patch> =
        leaves.iter().map(|p| Patch { material: scene.surfaces[p.surface as usize].material as u32, ..*p }).collect();
    let emission = patches.iter().map(|p| luminance[p.surface as usize]).collect();
    let faces = patches.iter().map(|p| p.face as usize + 1).max().unwrap_or(0);
    Ok(Mesh { patches, emission, faces })
}

/// The record of a hierarchy read from a file (no refinement passes), and its leaves' cuts.
fn record(
    scene: &Scene,
    parameters: Hierarchical,
    stored: StoredHierarchy,
    g: &Transport,
) -> (HierarchyRecord, Vec<f64>) {
    let leaves = g.hierarchy().map_or(&[][..], |o| o.leaves());
    let census = Census::of(&stored.structure.skeleton, &stored.structure.links, leaves);
    let record = HierarchyRecord {
        parameters,
        patch_size: scene.discretization.patch_size,
        roots: stored.roots,
        history: Vec::new(),
        census,
        structure: Some(stored.structure),
    };
    (record, stored.least)
}
