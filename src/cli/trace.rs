//! `ugo trace CASE`: the Monte Carlo references. Backward (`--camera NAME --spp S`):
//! per-pixel mean and standard-error images, linear EXR in cd/m² (and a PNG to look
//! at), and the readings of the case's probes with their standard errors. Forward (`--forward --photons P`): the estimate of the discrete field in the HDF5
//! layout of a solve, with standard errors. Both print their throughput.

use super::file_name;
use super::options::Discretize;
use super::render::chosen;
use super::{bar, check_writable, load, sibling};
use anyhow::{Result, bail};
use glam::DVec3;
use std::path::{Path, PathBuf};
use ugo::directions::DirectionSet;
use ugo::geometry::Mesh;
use ugo::io::{EstimateFile, OutputLock, auto_exposure, read_solution, write_estimate, write_exr_as, write_png};
use ugo::render::Projection;
use ugo::render::trace_camera;
use ugo::scene::{ProbeKind, Scene};
use ugo::trace::{TraceOptions, World, trace_photons, trace_probes};

/// What `ugo trace` was asked for.
pub struct TraceJob {
    pub cameras: Vec<String>,
    pub spp: usize,
    /// Paths per probe reading (backward).
    pub probe_samples: usize,
    /// `Some(P)`: forward with `P` photons instead of cameras.
    pub photons: Option<u64>,
    /// Forward: bin on the patches and cells of this solution instead of the uniform mesh.
    pub bins_of: Option<PathBuf>,
    pub options: TraceOptions,
    pub output: Option<PathBuf>,
}

pub fn run(case: &Path, d: &Discretize, job: &TraceJob) -> Result<()> {
    let scene = load(case, d)?;
    let (mesh, directions) = match &job.bins_of {
        Some(solution) => bins_of(case, &scene, solution, job)?,
        None => (uniform_mesh(&scene)?, scene.discretization.directions.set()),
    };
    let world = World::new(&scene, mesh);
    // Surfaces and luminaires both emit: the tracers start paths on the one and gather
    // (or, forward, start photons at) the other.
    let emitted = world.emitters.flux() + world.luminaires.flux();
    if (emitted.is_nan() || emitted <= 0.0) && world.openings.is_empty() {
        bail!("nothing in {} emits light: give a surface an emission or add a [[luminaire]]", case.display());
    }
    if let Some(photons) = job.photons {
        return forward(case, &scene, &world, &directions, job, photons);
    }
    if job.spp == 0 {
        bail!("--spp must be at least 1");
    }
    if scene.cameras.is_empty() && job.cameras.is_empty() && !scene.probes.is_empty() {
        return probes(&scene, &world, job);
    }
    camera_images(case, &scene, &world, job)?;
    if scene.probes.is_empty() { Ok(()) } else { probes(&scene, &world, job) }
}

/// The uniform mesh at the patch size, which the tracers bin into whatever the kernel,
/// refused before meshing when it would not fit in the memory limit.
fn uniform_mesh(scene: &Scene) -> Result<Mesh> {
    let (h, limit) = (scene.discretization.patch_size, scene.discretization.memory_limit);
    let directions = scene.discretization.directions.set();
    let f = ugo::kernel::Forecast::uniform(&scene.surfaces, scene.materials.len(), h, &directions);
    let need = f.mesh_bytes + f.vector_bytes;
    if need.is_nan() || need > limit as f64 {
        bail!(
            "the mesh would need {} for {:.3e} patches (estimated before meshing), over the limit of {}: \
             a larger --patch-size, or a higher --memory-limit if the machine has the RAM",
            super::bytes(f.mesh_bytes + f.vector_bytes),
            f.patches,
            super::bytes(limit as f64)
        );
    }
    Ok(Mesh::build(&scene.surfaces, h))
}

/// The patches and cells of the solution `solution` of the same case (`--bins-of`): the
/// hierarchy's leaves, for a forward estimate on them.
fn bins_of(case: &Path, scene: &Scene, solution: &Path, job: &TraceJob) -> Result<(Mesh, DirectionSet)> {
    if job.photons.is_none() {
        bail!("--bins-of names the bins of a forward trace: add --forward");
    }
    let stored = read_solution(solution)?;
    let (surfaces, materials) = (stored.scene.surfaces.len(), stored.scene.materials.len());
    if surfaces != scene.surfaces.len() || materials != scene.materials.len() {
        bail!(
            "{} solves another case: {surfaces} surfaces and {materials} materials against {} and {} in {}",
            solution.display(),
            scene.surfaces.len(),
            scene.materials.len(),
            case.display()
        );
    }
    Ok((stored.mesh, stored.directions))
}

/// What a trace keeps: every reflection order, or those up to `--max-order`.
fn orders_kept(job: &TraceJob) -> String {
    job.options.max_order.map_or("every order".to_string(), |n| format!("orders ≤ {n}"))
}

/// `ugo trace --forward`: photons into the (patch, cell) bins, written as HDF5.
fn forward(
    case: &Path,
    scene: &Scene,
    world: &World,
    directions: &DirectionSet,
    job: &TraceJob,
    photons: u64,
) -> Result<()> {
    let stem = case.file_stem().unwrap_or_default().to_string_lossy().into_owned();
    let order = orders_kept(job);
    if photons < 2 {
        bail!("--photons must be at least 2 (standard errors need two samples), got {photons}");
    }
    let output = job.output.clone().unwrap_or_else(|| PathBuf::from(format!("{stem}-forward.h5")));
    check_writable(&output)?;
    let _lock = OutputLock::take(&output)?;
    let progress = bar(photons, "photons");
    let estimate = trace_photons(world, directions, photons, &job.options, &|n| progress.inc(n));
    progress.finish_and_clear();
    super::stop::after_stage(|| "the forward trace".to_string(), &[&output])?;
    let file = EstimateFile {
        scene,
        mesh: &world.mesh,
        directions,
        estimate: &estimate,
        options: &job.options,
        emitted: world.photon_flux(),
    };
    write_estimate(&output, &file)?;
    let lit: Vec<f64> = estimate
        .luminance
        .iter()
        .zip(&estimate.luminance_error)
        .filter(|(l, e)| **e > 0.0 && **l > 0.0)
        .map(|(l, e)| e / l)
        .collect();
    say!("ugo trace --forward: {} ({}), seed {}, {order}", scene.name, case.display(), job.options.seed);
    say!("  patches N × cells K  {} × {} ({})", world.mesh.len(), directions.len(), directions.name());
    say!("  photons              {photons}");
    throughput(photons, estimate.rays, estimate.seconds, "photons");
    say!("  emitted flux         {:.6e} lm", world.photon_flux());
    say!("  scattered flux       {:.6e} ± {:.2e} lm", estimate.scattered.0, estimate.scattered.1);
    say!("  relative std. error  median {:.2e} over {} lit (patch, cell) bins", median(lit.clone()), lit.len());
    say!("  written              {}", output.display());
    Ok(())
}

/// Mean and standard-error images of each chosen camera.
fn camera_images(case: &Path, scene: &Scene, world: &World, job: &TraceJob) -> Result<()> {
    let stem = case.file_stem().unwrap_or_default().to_string_lossy().into_owned();
    let order = orders_kept(job);
    let cameras = chosen(&scene.cameras, &job.cameras, case)?;
    let dir = job.output.clone().unwrap_or_else(|| PathBuf::from("."));
    std::fs::create_dir_all(&dir).map_err(|e| anyhow::anyhow!("cannot create {}: {e}", dir.display()))?;
    for camera in cameras {
        let [w, h] = camera.resolution;
        let progress = bar(h as u64, &camera.name);
        let traced = trace_camera(world, camera, job.spp, &job.options, &|n| progress.inc(n));
        progress.finish_and_clear();
        let base = dir.join(format!("{stem}-{}-trace", file_name(&camera.name)));
        let (mean, error, png) = (sibling(&base, ".exr"), sibling(&base, "-stderr.exr"), sibling(&base, ".png"));
        super::stop::after_stage(|| format!("the trace of camera \"{}\"", camera.name), &[&mean, &error, &png])?;
        let seed = job.options.seed;
        write_exr_as(
            &mean,
            &traced.mean,
            &format!("luminance, cd/m2, backward Monte Carlo mean (ugo trace, {} spp, seed {seed})", job.spp),
        )?;
        write_exr_as(
            &error,
            &traced.standard_error,
            &format!("standard error of the luminance, cd/m2 (ugo trace, {} spp, seed {seed})", job.spp),
        )?;
        let view = Projection::of(camera);
        let light = |d: DVec3| world.sees_light(view.eye, d);
        let seen = traced.mean.luminance.iter().zip(view.pixels());
        let surfaces: Vec<f64> = seen.filter(|(_, p)| !view.any_sample(*p, &light)).map(|(l, _)| *l).collect();
        let white = auto_exposure(&surfaces);
        write_png(&png, &traced.mean, white)?;
        let (lo, hi) = traced.mean.range();
        let relative: Vec<f64> = traced
            .mean
            .luminance
            .iter()
            .zip(&traced.standard_error.luminance)
            .filter(|(m, _)| **m > 0.0)
            .map(|(m, e)| e / m)
            .collect();
        say!(
            "ugo trace: {} camera \"{}\" {w}×{h}, {} paths/pixel, seed {seed}, {order}",
            scene.name,
            camera.name,
            job.spp
        );
        throughput(traced.paths, traced.rays, traced.seconds, "paths");
        say!("  luminance            {lo:.4e} .. {hi:.4e} cd/m²");
        say!("  relative std. error  median {:.2e} per pixel", median(relative));
        say!("  {}\n  {}\n  {}", mean.display(), error.display(), png.display());
    }
    Ok(())
}

/// The probes' readings, `job.probe_samples` paths each.
fn probes(scene: &Scene, world: &World, job: &TraceJob) -> Result<()> {
    if job.probe_samples < 2 {
        bail!("--probe-samples must be at least 2 (standard errors need two samples)");
    }
    let start = std::time::Instant::now();
    let sensors = scene.probes.iter().filter(|p| p.kind == ProbeKind::Point).count() as u64;
    let progress = bar(2 * sensors * job.probe_samples as u64, "probe paths");
    let readings = trace_probes(world, &scene.probes, job.probe_samples, &job.options, &|n| progress.inc(n));
    progress.finish_and_clear();
    super::stop::after_stage(|| "the trace of the probes".to_string(), &[])?;
    say!(
        "  probes ({} paths each, {:.2} s)     luminance cd/m²            illuminance lx",
        job.probe_samples,
        start.elapsed().as_secs_f64()
    );
    for r in readings {
        say!(
            "    {:<22} {:>12.4} ± {:<10.2e} {:>12.4} ± {:<10.2e}",
            r.name,
            r.luminance.0,
            r.luminance.1,
            r.illuminance.0,
            r.illuminance.1
        );
    }
    Ok(())
}

fn throughput(samples: u64, rays: u64, seconds: f64, what: &str) {
    say!(
        "  time                 {seconds:.3} s: {:.3e} {what}/s, {:.3e} rays/s",
        samples as f64 / seconds,
        rays as f64 / seconds
    );
}

fn median(mut v: Vec<f64>) -> f64 {
    if v.is_empty() {
        return 0.0;
    }
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}
