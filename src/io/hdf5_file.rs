//! The HDF5 file of one solve (`docs/design.md` §8), readable with h5py or h5dump alone.
//!
//! Layout: `/mesh/{points,normals,areas,surface_id,material_id,vertices,vertex_count,face,
//! twin,surface_names,material_names}`, `/directions/{vectors,solid_angle,projected}`,
//! `/field/{luminance,emission,source,illuminance,direct_illuminance}` (emission is the
//! surfaces' own `L_e`, source the source term `L0 = L_e + B·D`; illuminance counts the
//! luminaires' direct light, which `direct_illuminance` holds alone), `/solver/{residual_history,applications,seconds}`,
//! `/compare/<method>/…` (the same histories per method, `ugo compare`),
//! `/orders/{orders,term_norms,partial_sums}` (the reflection-order record), `/norms` (attributes),
//! `/spectrum/…` (the leading eigenpairs of `K`, `spectrum_file.rs`),
//! `/energy/{surface_emitted,surface_absorbed}`,
//! `/probes/{name,kind,position,normal,luminance,illuminance}`,
//! `/observers/{name,position,look,ugr,ugr_limit,background_luminance,grid}` and
//! `/observers/sources/{observer,name,luminance,solid_angle,position_index}` (the UGR,
//! `observer_group.rs`), `/basis/{coefficients,psi,front,back}`
//! (a solve in a factored angular basis),
//! `/grids/<name>/{points,illuminance}` (with the statistics as attributes),
//! `/luminaires/{name,kind,position,direction,flux,distribution_flux,file_flux,on_surfaces,
//! group,file}` (one row per `[[luminaire]]` or array member; NaN where a value does not
//! apply, `group` empty for a source in no light group (an opening), `file` the
//! photometric file's name or empty; attribute `maintenance_factor`), the probes' `direct`
//! part in `/probes/direct`, `/light_groups` and `/light_scenes/<name>/…` (the case's
//! light scenes, `light_scene_group.rs`), and attributes on the root for
//! method, tolerance, iterations, timings, energy totals, the scene text and the version;
//! with `--save-kernel`, `/kernel` (`kernel_file.rs`).
//! The file is written under a temporary name and renamed when complete.

use super::dataset::{dataset, strings, text_attr};
use super::daylight_group::write_daylight;
use super::glare_grid_group::write_glare_grids;
use super::observer_group::write_observers;
use super::readout_group::{write_grids, write_probes};
use super::solution::Solution;
use crate::basis::{Factorization, MaterialFactor};
use crate::directions::DirectionSet;
use crate::geometry::Mesh;
use crate::luminaire::Light;
use crate::luminaire::LuminaireKind;
use crate::photometry::Distribution;
use crate::readout::illuminance::patch_illuminance;
use crate::scene::Scene;
use crate::solve::SolveInfo;
use crate::solve::norms::Norms;
use crate::solve::orders::OrderRecord;
use glam::DVec3;
use ndarray::{Array1, Array2, Array3};
use std::path::Path;

/// Writes the solution of `scene` to `path` (through `path.tmp`, renamed when complete).
pub fn write_solution(path: &Path, scene: &Scene, solution: &Solution) -> Result<(), super::IoError> {
    super::atomic(path, |tmp| write_to(tmp, scene, solution).map_err(|e| e.to_string()))
}

fn write_to(path: &Path, scene: &Scene, s: &Solution) -> hdf5::Result<()> {
    let file = hdf5::File::create(path)?;
    write_mesh(&file.create_group("mesh")?, scene, &s.model.mesh)?;
    write_directions(&file.create_group("directions")?, &s.model.kernel.directions)?;
    write_materials(&file.create_group("materials")?, scene, s)?;

    let field = file.create_group("field")?;
    dataset(&field, "luminance", &s.field.luminance)?;
    let k = s.model.kernel.cells();
    let own: Vec<f64> = s.model.mesh.emission.iter().flat_map(|&l| std::iter::repeat_n(l, k)).collect();
    dataset(&field, "emission", &Array3::from_shape_vec((s.model.mesh.len(), k, 1), own).map_err(shape_error)?)?;
    let source = Array3::from_shape_vec((s.model.mesh.len(), k, 1), s.model.l0.clone()).map_err(shape_error)?;
    dataset(&field, "source", &source)?;
    dataset(&field, "illuminance", &Array1::from(s.illuminance.to_vec()))?;
    dataset(&field, "direct_illuminance", &Array1::from(patch_illuminance(&s.model.direct.arriving, k)))?;

    let warnings: Vec<String> = s.warnings.iter().map(ToString::to_string).collect();
    strings(&file, "warnings", warnings.iter().map(String::as_str))?;
    let solver = file.create_group("solver")?;
    write_history(&solver, s.info())?;
    if s.runs.len() > 1 {
        let compare = file.create_group("compare")?;
        for run in &s.runs {
            let g = compare.create_group(&run.method.name())?;
            write_history(&g, &run.info)?;
            g.new_attr::<f64>().create("max_relative_difference")?.write_scalar(&run.difference)?;
            g.new_attr::<f64>().create("seconds")?.write_scalar(&run.info.seconds)?;
        }
    }
    if let Some(orders) = &s.orders {
        write_orders(&file.create_group("orders")?, orders, s.model.kernel.cells())?;
    }
    if let Some((factors, full_residual)) = &s.basis {
        write_basis(&file.create_group("basis")?, factors, &s.coefficients, *full_residual)?;
    }
    if let Some(norms) = &s.norms {
        write_norms(&file.create_group("norms")?, norms, s.params.tolerance)?;
    }
    if let Some(spectrum) = &s.spectrum {
        super::spectrum_file::write_spectrum(&file.create_group("spectrum")?, spectrum, s.model.kernel.cells())?;
    }

    let energy = file.create_group("energy")?;
    dataset(&energy, "surface_emitted", &Array1::from(s.energy.surface_emitted.clone()))?;
    dataset(&energy, "surface_absorbed", &Array1::from(s.energy.surface_absorbed.clone()))?;

    write_probes(&file.create_group("probes")?, &s.probes)?;
    write_observers(&file.create_group("observers")?, &s.observers)?;
    write_glare_grids(&file.create_group("glare_grids")?, &s.glare_grids)?;
    s.daylight.as_ref().map(|d| write_daylight(&file.create_group("daylight")?, d, &s.probes, &s.grids)).transpose()?;
    write_grids(&file.create_group("grids")?, &s.grids, &s.grid_errors, s.glare())?;
    write_luminaires(&file.create_group("luminaires")?, scene, s)?;
    if let Some(light) = &s.light_scenes {
        super::light_scene_group::write_light_scenes(&file, scene, &s.model, light)?;
    }
    if let Some(h) = &s.model.hierarchy {
        super::hierarchy_group::write_hierarchy(&file.create_group("hierarchy")?, h)?;
    }
    if let Some(fingerprint) = &s.kernel.save {
        super::kernel_file::write_kernel(&file.create_group("kernel")?, &s.model, fingerprint)?;
    }
    write_attributes(&file, scene, s)?;
    // Closed here, not dropped: the last metadata reaches the file now and its error counts.
    file.close()
}

/// `/mesh`: the patches and the names of surfaces and materials.
pub(super) fn write_mesh(g: &hdf5::Group, scene: &Scene, mesh: &Mesh) -> hdf5::Result<()> {
    let p = &mesh.patches;
    let n = p.len();
    let vec3 = |f: &dyn Fn(usize) -> glam::DVec3| Array2::from_shape_fn((n, 3), |(i, c)| f(i)[c]);
    dataset(g, "points", &vec3(&|i| p[i].centroid))?;
    dataset(g, "normals", &vec3(&|i| p[i].normal))?;
    dataset(g, "areas", &Array1::from_iter(p.iter().map(|q| q.area)))?;
    dataset(g, "exposed_areas", &Array1::from_iter(p.iter().map(|q| q.exposed)))?;
    dataset(g, "surface_id", &Array1::from_iter(p.iter().map(|q| q.surface)))?;
    dataset(g, "material_id", &Array1::from_iter(p.iter().map(|q| q.material)))?;
    let vertices = Array3::from_shape_fn((n, 4, 3), |(i, v, c)| {
        let vs = p[i].polygon.vertices();
        vs[v.min(vs.len() - 1)][c]
    });
    dataset(g, "vertices", &vertices)?;
    dataset(g, "vertex_count", &Array1::from_iter(p.iter().map(|q| q.polygon.vertices().len() as u8)))?;
    dataset(g, "face", &Array1::from_iter(p.iter().map(|q| q.face)))?;
    dataset(g, "twin", &Array1::from_iter(p.iter().map(|q| q.twin)))?;
    strings(g, "surface_names", scene.surfaces.iter().map(|x| x.name.as_str()))?;
    strings(g, "material_names", scene.materials.iter().map(|x| x.name.as_str()))
}

/// `/directions`: the cells' representative vectors, solid angles and projected solid angles.
pub(super) fn write_directions(g: &hdf5::Group, directions: &DirectionSet) -> hdf5::Result<()> {
    let cells = directions.cells();
    dataset(g, "vectors", &Array2::from_shape_fn((cells.len(), 3), |(k, c)| cells[k].direction[c]))?;
    dataset(g, "solid_angle", &Array1::from_iter(cells.iter().map(|c| c.solid_angle)))?;
    dataset(g, "projected", &Array1::from_iter(cells.iter().map(|c| c.projected)))
}

fn write_history(g: &hdf5::Group, info: &SolveInfo) -> hdf5::Result<()> {
    dataset(g, "residual_history", &Array1::from(info.residual_history.clone()))?;
    let applications: Vec<u64> = info.application_history.iter().map(|&a| a as u64).collect();
    dataset(g, "applications", &Array1::from(applications))?;
    dataset(g, "seconds", &Array1::from(info.time_history.clone()))
}

fn write_orders(g: &hdf5::Group, orders: &OrderRecord, k: usize) -> hdf5::Result<()> {
    dataset(g, "term_norms", &Array1::from(orders.term_norms.clone()))?;
    let which: Vec<u64> = orders.partial_sums.iter().map(|(n, _)| *n as u64).collect();
    dataset(g, "orders", &Array1::from(which))?;
    let n = orders.partial_sums.first().map_or(0, |(_, x)| x.len() / k);
    let sums = ndarray::Array4::from_shape_fn((orders.partial_sums.len(), n, k, 1), |(o, i, c, _)| {
        orders.partial_sums[o].1[i * k + c]
    });
    dataset(g, "partial_sums", &sums)
}

fn write_norms(g: &hdf5::Group, norms: &Norms, tolerance: f64) -> hdf5::Result<()> {
    // matrix-free, ‖K‖_F and ‖K‖₂ are not computed: absent, with `matrix_free` 1 and the bound
    let two = norms.two.map(|t| [("two", t.value), ("two_iterations", t.iterations as f64)]);
    let optional = norms.frobenius.map(|f| ("frobenius", f)).into_iter().chain(two.into_iter().flatten());
    let values = [
        ("one", norms.one),
        ("infinity", norms.infinity),
        ("two_bound", norms.two_bound()),
        ("matrix_free", norms.matrix_free.is_some() as u8 as f64),
        ("spectral_radius", norms.spectral_radius.value),
        ("spectral_radius_iterations", norms.spectral_radius.iterations as f64),
        ("spectral_radius_converged", norms.spectral_radius.converged as u8 as f64),
        ("condition_infinity", norms.condition_infinity),
        ("predicted_neumann_iterations", norms.predicted_iterations(tolerance)),
    ];
    for (name, value) in values.into_iter().chain(optional) {
        g.new_attr::<f64>().create(name)?.write_scalar(&value)?;
    }
    Ok(())
}

fn write_materials(g: &hdf5::Group, scene: &Scene, s: &Solution) -> hdf5::Result<()> {
    let blocks = &s.model.kernel.blocks;
    let k = s.model.kernel.cells();
    strings(g, "name", scene.materials.iter().map(|m| m.name.as_str()))?;
    let reflect = Array3::from_shape_fn((blocks.len(), k, k), |(m, a, b)| blocks[m].at(a, b));
    dataset(g, "reflection", &reflect)?;
    let transmit = Array3::from_shape_fn((blocks.len(), k, k), |(m, a, b)| blocks[m].transmit_at(a, b).unwrap_or(0.0));
    dataset(g, "transmission", &transmit)
}

/// `/basis/{coefficients (N × M), psi, front, back (materials × K × M)}` and attributes.
/// `coefficients` are `c[i·M + n]`, the field `L0 + Ψ c`; `full_residual` is
/// `‖L0 + K x − x‖₂ / ‖L0‖₂` of the reconstructed field in the full system.
fn write_basis(g: &hdf5::Group, f: &Factorization, coefficients: &[f64], full_residual: f64) -> hdf5::Result<()> {
    let (m, k, count) = (f.m, f.k, f.materials.len());
    let n = coefficients.len() / m.max(1);
    dataset(g, "coefficients", &Array2::from_shape_fn((n, m), |(i, c)| coefficients[i * m + c]))?;
    let stack = |pick: fn(&MaterialFactor) -> Option<&Vec<f64>>| {
        Array3::from_shape_fn((count, k, m), |(a, r, c)| pick(&f.materials[a]).map_or(0.0, |v| v[r * m + c]))
    };
    dataset(g, "psi", &stack(|x| Some(&x.psi)))?;
    dataset(g, "front", &stack(|x| Some(&x.front)))?;
    dataset(g, "back", &stack(|x| x.back.as_ref()))?;
    text_attr(g, "basis", &f.basis.name())?;
    for (name, value) in [("m", m as f64), ("rank", f.rank as f64), ("full_residual", full_residual)] {
        g.new_attr::<f64>().create(name)?.write_scalar(&value)?;
    }
    Ok(())
}

/// Copies of the files the case names (OBJ, photometric): `/case_files/paths` and the bytes
/// of file `i` in `/case_files/<i>` (u8), so that the solution is read back without them.
fn write_case_files(g: &hdf5::Group, scene: &Scene) -> hdf5::Result<()> {
    let paths: Vec<String> = scene.files.iter().map(|f| f.path.display().to_string()).collect();
    strings(g, "paths", paths.iter().map(String::as_str))?;
    for (i, f) in scene.files.iter().enumerate() {
        dataset(g, &i.to_string(), &Array1::from(f.bytes.clone()))?;
    }
    Ok(())
}

/// The attributes every file of a field carries: method, scene, version, direction set, units
/// (and the case's own files, `/case_files`).
pub(super) fn write_identity(
    file: &hdf5::File,
    method: &str,
    scene: &Scene,
    directions: &DirectionSet,
) -> hdf5::Result<()> {
    text_attr(file, "method", method)?;
    write_case(file, scene)?;
    text_attr(file, "version", env!("CARGO_PKG_VERSION"))?;
    text_attr(file, "directions", directions.name())?;
    text_attr(file, "units", "luminance cd/m2, illuminance lx, flux lm, lengths m")
}

/// The case of a file: its name, path and text (root attributes, [`CASE_ATTRIBUTES`]) and
/// its own files (`/case_files`); what `ugo readout` replaces with the edited case.
pub(super) fn write_case(file: &hdf5::File, scene: &Scene) -> hdf5::Result<()> {
    let [name, path, text] = CASE_ATTRIBUTES;
    text_attr(file, name, &scene.name)?;
    text_attr(file, path, &scene.path.display().to_string())?;
    text_attr(file, text, &scene.source)?;
    write_case_files(&file.create_group("case_files")?, scene)
}

/// The root attributes [`write_case`] writes.
pub(super) const CASE_ATTRIBUTES: [&str; 3] = ["scene_name", "scene_file", "scene_text"];

fn write_luminaires(g: &hdf5::Group, scene: &Scene, s: &Solution) -> hdf5::Result<()> {
    let sources = &s.model.sources;
    let n = sources.len();
    strings(g, "name", sources.iter().map(|l| l.name.as_str()))?;
    let kinds = scene.luminaires.iter().map(|l| match &l.kind {
        LuminaireKind::Parallel { .. } => "parallel",
        LuminaireKind::Window { .. } => "window",
        LuminaireKind::Point(p) => match &p.distribution {
            Distribution::Isotropic { .. } => "isotropic",
            Distribution::Lambertian { .. } => "lambertian",
            Distribution::Table(_) => "file",
        },
    });
    strings(g, "kind", kinds)?;
    let (position, direction): (Vec<DVec3>, Vec<DVec3>) = sources
        .iter()
        .map(|l| match &l.light {
            Light::Point { position, frame, .. } => (*position, -frame.normal),
            Light::Parallel { direction, .. } => (DVec3::NAN, *direction),
            Light::Window { window, .. } => (window.polygon.centroid(), window.polygon.normal()),
        })
        .unzip();
    dataset(g, "position", &Array2::from_shape_fn((n, 3), |(i, c)| position[i][c]))?;
    dataset(g, "direction", &Array2::from_shape_fn((n, 3), |(i, c)| direction[i][c]))?;
    dataset(g, "flux", &Array1::from(s.energy.luminaire_emitted.clone()))?;
    let distribution = sources.iter().map(|l| match &l.light {
        Light::Point { distribution, .. } => distribution.flux(),
        Light::Parallel { .. } | Light::Window { .. } => f64::NAN,
    });
    dataset(g, "distribution_flux", &Array1::from_iter(distribution))?;
    let stated = sources.iter().map(|l| match &l.light {
        Light::Point { distribution: Distribution::Table(t), .. } => t.stated_flux.unwrap_or(f64::NAN),
        _ => f64::NAN,
    });
    dataset(g, "file_flux", &Array1::from_iter(stated))?;
    dataset(g, "on_surfaces", &Array1::from(s.model.direct.intercepted.clone()))?;
    let lighting = &scene.lighting;
    let group = |i: usize| lighting.groups.iter().find(|g| g.luminaires.contains(&i)).map_or("", |g| &g.name);
    strings(g, "group", (0..n).map(group))?;
    let files: Vec<String> = scene.luminaires.iter().map(|l| photometric_file(l).unwrap_or_default()).collect();
    strings(g, "file", files.iter().map(String::as_str))?;
    g.new_attr::<f64>().create("maintenance_factor")?.write_scalar(&lighting.maintenance_factor)
}

/// The name of the photometric file a luminaire's distribution was read from, if any.
fn photometric_file(l: &crate::luminaire::Luminaire) -> Option<String> {
    match &l.kind {
        LuminaireKind::Point(p) => p.file.as_ref()?.file_name().map(|f| f.to_string_lossy().into_owned()),
        LuminaireKind::Parallel { .. } | LuminaireKind::Window { .. } => None,
    }
}

fn write_attributes(file: &hdf5::File, scene: &Scene, s: &Solution) -> hdf5::Result<()> {
    let (st, info) = (&s.model.stats, s.info());
    write_identity(file, info.method.name(), scene, &s.model.kernel.directions)?;
    let d = &scene.discretization;
    text_attr(file, "kernel", d.kernel.name())?;
    if let Some(chosen) = d.chosen_by_size {
        text_attr(file, "kernel_chosen_by_size", &chosen.to_string())?;
    }
    let numbers: [(&str, f64); 18] = [
        ("tolerance", s.params.tolerance),
        ("max_iterations", s.params.max_iterations as f64),
        ("iterations", info.iterations as f64),
        ("kernel_applications", info.applications as f64),
        ("residual", info.residual()),
        ("patch_size", d.patch_size),
        ("nonzeros", s.model.kernel.g.nnz() as f64),
        ("mesh_seconds", st.mesh_seconds),
        ("bvh_seconds", st.bvh_seconds),
        ("assembly_seconds", st.kernel_seconds),
        ("luminaire_seconds", st.light_seconds),
        ("solve_seconds", info.seconds),
        ("balance_max_correction", st.balance.map_or(0.0, |b| b.max_correction)),
        ("flux_emitted", s.energy.emitted),
        ("flux_absorbed", s.energy.absorbed),
        ("flux_escaped", s.energy.escaped),
        ("flux_imbalance", s.energy.imbalance),
        ("occlusion_rays", st.rays as f64),
    ];
    for (name, value) in numbers {
        file.new_attr::<f64>().create(name)?.write_scalar(&value)?;
    }
    Ok(())
}

pub(super) fn shape_error(e: ndarray::ShapeError) -> hdf5::Error {
    hdf5::Error::from(e.to_string())
}
