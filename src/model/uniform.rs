//! The uniform model (`docs/design.md` §3): the uniform mesh, every facing pair of patches
//! integrated and balanced into `G`, the light by way of plane mirrors carried by images
//! (`docs/mirrors.md`), the luminaires' direct light on every patch.

use super::range::{check_blocks, check_source, check_transport};
use super::source::source_term;
use super::system::{AssemblyStats, Model, ModelError};
use crate::geometry::Mesh;
use crate::kernel::{Assembled, Forecast, Kernel, Transport, TransportMatrix, assemble};
use crate::luminaire::{Source, direct_light};
use crate::material::MaterialModel;
use crate::progress::Progress;
use crate::scene::Scene;
use crate::transfer::exposure::measure_exposure;
use crate::transfer::form_factor::Quadrature;
use crate::transfer::image::{PlaneMirror, plane_mirrors};
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
    let visibility = Visibility::build_for(&scene.surfaces, &mesh);
    measure_exposure(&mut mesh, &visibility, progress);
    crate::interrupt::check(|| "the patches' exposed areas".into())?;
    let bvh_seconds = t.elapsed().as_secs_f64();
    let t = Instant::now();
    let n = mesh.len() as u64;
    progress.begin("assembly", n * n.saturating_sub(1) / 2);
    let mirrors = mirrors_of(scene, &mesh);
    let quadrature = Quadrature::default();
    let Assembled { g, balance, pairs, rays } =
        assemble(&mesh, &visibility, &directions, &quadrature, &mirrors, &|done| progress.advance(done))?;
    progress.end();
    let blocks: Vec<_> = scene.materials.iter().map(|m| m.model.block(&directions)).collect();
    check_blocks(scene, &blocks, directions.len())?;
    let g = Transport::Uniform(TransportMatrix::new(g, d.precision));
    check_transport(scene, &mesh, &g, directions.len())?;
    let kernel = Kernel::on_mesh(g, &mesh, directions, blocks);
    let kernel_seconds = t.elapsed().as_secs_f64();
    let t = Instant::now();
    let sources: Vec<Source> = scene.luminaires.iter().map(Source::of).collect();
    let direct = direct_light(&sources, &mesh, &visibility, &kernel.directions, &[], &mirrors);
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
    Ok(Model { mesh, visibility, faces, kernel, materials, l0, sources, direct, mirrors, stats, hierarchy: None })
}

/// The plane mirrors of `scene` meshed into `mesh` (`transfer::image::plane_mirrors`), whose
/// light the uniform kernel carries by images. None when a luminaire is parallel light or an
/// opening: only a point source's light is mirrored by an image (`luminaire::patch_lights`),
/// so their mirrors keep reflecting cell to cell.
pub fn mirrors_of(scene: &Scene, mesh: &Mesh) -> Vec<PlaneMirror> {
    if !scene.luminaires.iter().map(Source::of).all(|s| s.mirrored_by_image()) {
        return Vec::new();
    }
    let reflectance: Vec<Option<f64>> = scene
        .materials
        .iter()
        .map(|m| match m.model {
            MaterialModel::Mirror { reflectance } => Some(reflectance),
            _ => None,
        })
        .collect();
    plane_mirrors(mesh, &reflectance)
}
