//! The discretized problem of a scene: mesh, visibility, kernel `K = B·G` and source
//! `L0` (`design.md` §6, the arrows from Scene to Kernel): the surfaces' own emission plus
//! the luminaires' direct light reflected once, `L0 = L_e + B·D` (`crate::luminaire`).
//!
//! The kernel's memory is estimated before assembly and a kernel over the limit is
//! refused with the estimate and the ways out.

use crate::directions::DirectionSet;
use crate::geometry::Mesh;
use crate::kernel::{Estimate, Footprint, Kernel, Precision, TooLarge, Transport, TransportMatrix, assemble};
use crate::luminaire::{DirectLight, Source, direct_light};
use crate::scene::Scene;
use crate::transfer::form_factor::Quadrature;
use crate::visibility::{Faces, Visibility};
use std::time::Instant;

/// How a scene is discretized.
#[derive(Debug, Clone, PartialEq)]
pub struct ModelOptions {
    /// Target patch edge length, m.
    pub patch_size: f64,
    /// Direction cells of every patch.
    pub directions: DirectionSet,
    /// Largest kernel memory allowed, bytes.
    pub memory_limit: u64,
    pub quadrature: Quadrature,
    /// Precision of the stored `G`.
    pub precision: Precision,
}

impl ModelOptions {
    /// The scene's own discretization with the default limits.
    pub fn of(scene: &Scene) -> ModelOptions {
        ModelOptions {
            patch_size: scene.discretization.patch_size,
            directions: scene.discretization.directions.set(),
            memory_limit: crate::kernel::memory::default_limit(),
            quadrature: Quadrature::default(),
            precision: Precision::Double,
        }
    }
}

/// Timings and counts of the assembly.
#[derive(Debug, Clone)]
pub struct AssemblyStats {
    pub mesh_seconds: f64,
    pub bvh_seconds: f64,
    pub kernel_seconds: f64,
    /// Time spent on the luminaires' direct light.
    pub light_seconds: f64,
    pub pairs: usize,
    pub rays: usize,
    pub balance: crate::kernel::BalanceReport,
}

/// A scene discretized into the linear system `x = L0 + K x`.
pub struct Model {
    pub mesh: Mesh,
    pub visibility: Visibility,
    /// The patches of each face, for probes and grids.
    pub faces: Faces,
    pub kernel: Kernel,
    /// Source term `L0(i,k)`, flat, `x[i·K + k]`.
    pub l0: Vec<f64>,
    /// The luminaires, placed.
    pub sources: Vec<Source>,
    /// Their direct light on every (patch, cell).
    pub direct: DirectLight,
    pub stats: AssemblyStats,
}

impl Model {
    /// Meshes the scene only (for estimates).
    pub fn mesh(scene: &Scene, options: &ModelOptions) -> Mesh {
        Mesh::build(&scene.surfaces, options.patch_size)
    }

    /// Builds the full model. `progress(total)` is called once with the number of pair
    /// evaluations ahead, then `step(done)` as they finish.
    pub fn build(
        scene: &Scene,
        options: &ModelOptions,
        start: &dyn Fn(u64),
        step: &(dyn Fn(u64) + Sync),
    ) -> Result<Model, TooLarge> {
        let t = Instant::now();
        let mesh = Mesh::build(&scene.surfaces, options.patch_size);
        let directions = options.directions.clone();
        let estimate = Estimate::of(&mesh, &directions);
        Footprint {
            what: "kernel G",
            bytes: estimate.peak_bytes(),
            nonzeros: estimate.nonzeros,
            patches: estimate.patches,
            cells: estimate.cells,
        }
        .check(options.memory_limit)?;
        let mesh_seconds = t.elapsed().as_secs_f64();
        let t = Instant::now();
        let visibility = Visibility::build(&mesh);
        let bvh_seconds = t.elapsed().as_secs_f64();
        let t = Instant::now();
        let n = mesh.len() as u64;
        start(n * n.saturating_sub(1) / 2);
        let Transport { g, balance, pairs, rays } =
            assemble(&mesh, &visibility, &directions, &options.quadrature, step);
        let blocks = scene.materials.iter().map(|m| m.model.block(&directions)).collect();
        let patch_material = mesh.patches.iter().map(|p| p.material).collect();
        let twin = mesh.patches.iter().map(|p| p.twin).collect();
        let g = TransportMatrix::new(g, options.precision);
        let kernel = Kernel { g, directions, blocks, patch_material, twin };
        let kernel_seconds = t.elapsed().as_secs_f64();
        let t = Instant::now();
        let sources: Vec<Source> = scene.luminaires.iter().map(Source::of).collect();
        let direct = direct_light(&sources, &mesh, &visibility, &kernel.directions);
        let stats = AssemblyStats {
            mesh_seconds,
            bvh_seconds,
            kernel_seconds,
            light_seconds: t.elapsed().as_secs_f64(),
            pairs,
            rays: rays + direct.rays,
            balance,
        };
        let l0 = source_term(&kernel, &direct, &mesh.emission);
        let faces = Faces::of(&mesh);
        Ok(Model { mesh, visibility, faces, kernel, l0, sources, direct, stats })
    }

    /// `L0` again, after the material blocks of the kernel changed.
    pub fn source_term(&self) -> Vec<f64> {
        source_term(&self.kernel, &self.direct, &self.mesh.emission)
    }
}

/// `L0 = L_e + B·D`: each patch's own emission `emission[i]` in every cell, plus the
/// luminaires' direct light reflected (and transmitted) once by the kernel's blocks.
fn source_term(kernel: &Kernel, direct: &DirectLight, emission: &[f64]) -> Vec<f64> {
    let k = kernel.cells();
    let mut l0 = vec![0.0; direct.arriving.len()];
    kernel.apply_materials(&direct.arriving, &mut l0);
    for (cells, &emitted) in l0.chunks_mut(k).zip(emission) {
        cells.iter_mut().for_each(|l| *l += emitted);
    }
    l0
}
