//! The HDF5 file of a forward Monte Carlo estimate (`ugo trace --forward`): the layout of
//! a solve (`docs/design.md` §8, `hdf5_file.rs`) so that `ugo render`, `ugo agree` and h5py
//! read it alike, plus the standard errors.
//!
//! `/mesh/…`, `/directions/…` as a solve; `/field/{luminance,emission}` (N×K×1, cd/m²),
//! `/field/standard_error` (N×K×1), `/field/illuminance` and
//! `/field/illuminance_standard_error` (N, lx); `/trace` attributes `photons`, `seed`,
//! `max_order` (−1: every order), `rays`, `seconds`, `emitted_flux`, `scattered_flux` and
//! `scattered_flux_error` (lm); root attributes `method = "forward"`, the scene, the
//! version, the direction set, the units and `patch_size`.

use super::IoError;
use super::dataset::dataset;
use super::hdf5_file::{shape_error, write_directions, write_identity, write_mesh};
use crate::directions::DirectionSet;
use crate::geometry::Mesh;
use crate::scene::Scene;
use crate::trace::{FieldEstimate, TraceOptions};
use ndarray::{Array1, Array3};
use std::path::Path;

/// Everything a forward run produced.
pub struct EstimateFile<'a> {
    /// The case traced.
    pub scene: &'a Scene,
    /// The patches of the bins.
    pub mesh: &'a Mesh,
    /// The direction cells of the bins.
    pub directions: &'a DirectionSet,
    /// The estimate of the field and its standard errors.
    pub estimate: &'a FieldEstimate,
    /// The options of the run (photons, seed, …).
    pub options: &'a TraceOptions,
    /// Total emitted flux, lm.
    pub emitted: f64,
}

/// Writes `e` to `path` (through `path.tmp`, renamed when complete).
pub fn write_estimate(path: &Path, e: &EstimateFile) -> Result<(), IoError> {
    super::atomic(path, |tmp| write_to(tmp, e).map_err(|err| err.to_string()))
}

fn write_to(path: &Path, e: &EstimateFile) -> hdf5::Result<()> {
    let file = hdf5::File::create(path)?;
    write_mesh(&file.create_group("mesh")?, e.scene, e.mesh)?;
    write_directions(&file.create_group("directions")?, e.directions)?;
    let (n, k) = (e.mesh.len(), e.directions.len());
    let field = file.create_group("field")?;
    let cube = |v: Vec<f64>| Array3::from_shape_vec((n, k, 1), v).map_err(shape_error);
    let est = e.estimate;
    dataset(&field, "luminance", &cube(est.luminance.clone())?)?;
    dataset(&field, "standard_error", &cube(est.luminance_error.clone())?)?;
    let emission = e.mesh.emission.iter().flat_map(|&l| std::iter::repeat_n(l, k)).collect();
    dataset(&field, "emission", &cube(emission)?)?;
    dataset(&field, "illuminance", &Array1::from(est.illuminance.clone()))?;
    dataset(&field, "illuminance_standard_error", &Array1::from(est.illuminance_error.clone()))?;
    let trace = file.create_group("trace")?;
    for (name, value) in [("photons", est.photons), ("seed", e.options.seed), ("rays", est.rays)] {
        trace.new_attr::<u64>().create(name)?.write_scalar(&value)?;
    }
    let numbers = [
        ("max_order", e.options.max_order.map_or(-1.0, |m| m as f64)),
        ("seconds", est.seconds),
        ("emitted_flux", e.emitted),
        ("scattered_flux", est.scattered.0),
        ("scattered_flux_error", est.scattered.1),
    ];
    for (name, value) in numbers {
        trace.new_attr::<f64>().create(name)?.write_scalar(&value)?;
    }
    write_identity(&file, "forward", e.scene, e.directions)?;
    file.new_attr::<f64>().create("patch_size")?.write_scalar(&e.scene.discretization.patch_size)?;
    // Closed here, not dropped: the last metadata reaches the file now and its error counts.
    file.close()
}
