//! The uniform model (`docs/design.md` §3): the uniform mesh, every facing pair of patches
//! integrated and balanced into `G`, the luminaires' direct light on every patch.

use super::range::{check_blocks, check_source, check_transport};
use super::source::source_term;
use super::system::{AssemblyStats, Model, ModelError};
use crate::geometry::Mesh;
use crate::kernel::{Assembled, Forecast, Kernel, Transport, TransportMatrix, assemble};
use crate::luminaire::{Source, direct_light};
use crate::progress::Progress;
use crate::scene::Scene;
use crate::transfer::exposure::measure_exposure;
use crate::transfer::form_factor::Quadrature;
use crate::visibility::{Faces, Visibility};
use std::time::Instant;

/// Meshes, checks the kernel's estimate against the memory limit, assembles; checks the
/// kernel and the source term for values out of range (`super::range`).
pub fn build(scene: &Scene, progress: &dyn Progress) -> Result<Model, ModelError> {
    let t = Instant::now();
    let d = &scene.discretization;
    let mut mesh = Mesh::build(&scene.surfaces, d.patch_size);
    let directions = d.directions.set();
    Forecast::counted(&mesh, scene.materials.len(), &directions).check(d.memory_limit)?;
    let mesh_seconds = t.elapsed().as_secs_f64();
    let t = Instant::now();
    let visibility = Visibility::build(&mesh);
    measure_exposure(&mut mesh, &visibility);
    let bvh_seconds = t.elapsed().as_secs_f64();
    let t = Instant::now();
    let n = mesh.len() as u64;
    progress.begin("assembly", n * n.saturating_sub(1) / 2);
    let Assembled { g, balance, pairs, rays } =
        assemble(&mesh, &visibility, &directions, &Quadrature::default(), &|done| progress.advance(done))?;
    progress.end();
    let blocks: Vec<_> = scene.materials.iter().map(|m| m.model.block(&directions)).collect();
    check_blocks(scene, &blocks, directions.len())?;
    let g = Transport::Uniform(TransportMatrix::new(g, d.precision));
    check_transport(scene, &mesh, &g, directions.len())?;
    let kernel = Kernel::on_mesh(g, &mesh, directions, blocks);
    let kernel_seconds = t.elapsed().as_secs_f64();
    let t = Instant::now();
    let sources: Vec<Source> = scene.luminaires.iter().map(Source::of).collect();
    let direct = direct_light(&sources, &mesh, &visibility, &kernel.directions, &[]);
    let stats = AssemblyStats {
        mesh_seconds,
        bvh_seconds,
        kernel_seconds,
        light_seconds: t.elapsed().as_secs_f64(),
        pairs,
        rays: rays + direct.rays,
        balance: Some(balance),
    };
    let l0 = source_term(&kernel.blocks, &mesh, &direct, kernel.cells());
    check_source(scene, &mesh, &direct, &l0, kernel.cells())?;
    let faces = Faces::of(&mesh);
    let materials = scene.materials.iter().map(|m| m.model.clone()).collect();
    Ok(Model { mesh, visibility, faces, kernel, materials, l0, sources, direct, stats, hierarchy: None })
}
