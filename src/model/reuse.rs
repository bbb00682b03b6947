//! The uniform model around a stored `G` (issue 15, `docs/kernel-file.md`): the mesh and
//! its ray caster rebuilt from the case (cheap), `G` as read from a kernel file instead of
//! assembled, the blocks `B` and the luminaires' direct light `D` as stored or, when only
//! they changed, rebuilt from the case, and `L0 = L_e + B·D` (`docs/design.md` §2, §3).

use super::source::source_term;
use super::system::{AssemblyStats, Model};
use super::uniform::mirrors_of;
use crate::geometry::Mesh;
use crate::kernel::{Kernel, Transport, TransportMatrix};
use crate::luminaire::{DirectLight, Source, direct_light};
use crate::material::Block;
use crate::scene::Scene;
use crate::visibility::{Faces, Visibility};
use std::time::Instant;
use thiserror::Error;

/// What a kernel file supplies to the model.
pub struct StoredParts {
    /// The stored transport `G`.
    pub g: TransportMatrix,
    /// The stored blocks, or `None` to build them from the case.
    pub blocks: Option<Vec<Block>>,
    /// The stored direct light, or `None` to trace it for the case's luminaires.
    pub direct: Option<DirectLight>,
    /// Seconds spent reading them.
    pub read_seconds: f64,
}

/// A stored `G` that does not fit the case's mesh.
#[derive(Debug, Error)]
#[error(
    "the stored G has {rows} rows, but the case meshes into {patches} patches × {cells} cells = {} unknowns",
    patches * cells
)]
pub struct NotThisMesh {
    /// Rows of the stored `G`.
    pub rows: usize,
    /// Patches of the case's mesh.
    pub patches: usize,
    /// Direction cells per patch of the case.
    pub cells: usize,
}

impl Model {
    /// The uniform model of `scene` around the stored parts: nothing is assembled.
    pub fn with_kernel(scene: &Scene, stored: StoredParts) -> Result<Model, NotThisMesh> {
        let t = Instant::now();
        let mesh = Mesh::build(&scene.surfaces, scene.discretization.patch_size);
        let directions = scene.discretization.directions.set();
        let (rows, patches, cells) = (stored.g.rows(), mesh.len(), directions.len());
        if rows != patches * cells {
            return Err(NotThisMesh { rows, patches, cells });
        }
        let mesh_seconds = t.elapsed().as_secs_f64();
        let t = Instant::now();
        let visibility = Visibility::build(&mesh);
        let bvh_seconds = t.elapsed().as_secs_f64();
        let blocks =
            stored.blocks.unwrap_or_else(|| scene.materials.iter().map(|m| m.model.block(&directions)).collect());
        let kernel = Kernel::on_mesh(Transport::Uniform(stored.g), &mesh, directions, blocks);
        let t = Instant::now();
        let sources: Vec<Source> = scene.luminaires.iter().map(Source::of).collect();
        let mirrors = mirrors_of(scene, &mesh);
        let direct = stored
            .direct
            .unwrap_or_else(|| direct_light(&sources, &mesh, &visibility, &kernel.directions, &[], &mirrors));
        let stats = AssemblyStats {
            mesh_seconds,
            bvh_seconds,
            kernel_seconds: stored.read_seconds,
            light_seconds: t.elapsed().as_secs_f64(),
            pairs: 0,
            rays: direct.rays,
            balance: None,
        };
        let l0 = source_term(&kernel.blocks, &mesh, &direct, kernel.cells());
        let faces = Faces::of(&mesh);
        let materials = scene.materials.iter().map(|m| m.model.clone()).collect();
        Ok(Model { mesh, visibility, faces, kernel, materials, l0, sources, direct, mirrors, stats, hierarchy: None })
    }
}
