//! The light scenes of a solve in its HDF5 file (`docs/design.md` §8), and one of them read
//! back for `ugo render --light-scene NAME`.
//!
//! `/light_groups/{name (G), luminance (G×N×K×1), emission (G×N), direct (G×N×K×1),
//! intercepted (G×L), scene_names (S), factors (S×G), applications, iterations,
//! start_residual, residual, seconds (G)}`: each group's field alone (cd/m²; any light
//! scene is `Σ_g factors[s, g] · luminance[g]`), the patches' own emission of its surfaces,
//! its luminaires' direct light `D_g` on the patches (in the units of `G x`) and the flux
//! each of the L luminaires lands (lm), and what its solve cost (kernel applications, the
//! relative residual of the projected start and of the solution, s); attribute
//! `maintenance_factor`. Files solved before `direct` was stored have neither it nor
//! `intercepted` (`ugo readout` traces the groups' light again). `/light_groups/grid_readings`
//! (G×P×2) and `/light_groups/bar_samples` (G×M×2): each group's readings of the grids'
//! points (illuminance and its direct part, lx) and residual samples at the probes and grids
//! (`π r` in lx and the albedo of the point seen; `readout::group_readouts`), every light
//! scene's grid readings and bars being those of `Σ_g factors[s, g] · …[g]`; absent from
//! files solved before (`ugo readout` reads them and stores them). `/light_scenes/<name>/field/{luminance,emission,source,
//! illuminance,direct_illuminance}`, `/light_scenes/<name>/probes/…` and
//! `/light_scenes/<name>/grids/<grid>/…` as `/field`, `/probes` and `/grids` of the file,
//! for the light scene; its attributes: `factors` (G) and `flux_emitted`, `flux_absorbed`,
//! `flux_escaped`, `flux_imbalance` (lm).

use super::IoError;
use super::dataset::{dataset, strings};
use super::glare_grid_group::write_glare_grids;
use super::observer_group::write_observers;
use super::read::StoredSolution;
use super::readout_group::{write_grids, write_probes};
use crate::luminaire::DirectLight;
use crate::model::Model;
use crate::readout::energy::EnergyBalance;
use crate::readout::error_bar::Sample;
use crate::readout::field::Field;
use crate::readout::glare_grid::GlareGridReading;
use crate::readout::grid::GridReading;
use crate::readout::grid_error::GridErrorBars;
use crate::readout::grid_ugr::GlareReadings;
use crate::readout::group_readouts::GroupReadouts;
use crate::readout::probe::ProbeReading;
use crate::readout::residual_samples::ResidualSamples;
use crate::readout::ugr::UgrReading;
use crate::scene::{LightScene, Scene};
use crate::solve::Successive;
use hdf5::types::VarLenUnicode;
use ndarray::{Array1, Array2, Array3, Array4};
use std::path::Path;

/// The light scenes of a case: one field per group, and every light scene's readouts.
pub struct LightScenes {
    /// One field per group of sources.
    pub groups: Vec<GroupField>,
    /// One entry per `[[light_scene]]`.
    pub scenes: Vec<LightSceneField>,
    /// Each group's grid readings and residual samples, from which every light scene's
    /// grid readings and error bars follow; `None` without light scenes.
    pub shared: Option<GroupReadouts>,
}

/// One group's field alone, and its solve.
pub struct GroupField {
    /// The group's name.
    pub name: String,
    /// The emission of its surfaces per patch, cd/m².
    pub emission: Vec<f64>,
    /// Its luminaires' direct light on the patches and the flux each luminaire lands.
    pub direct: DirectLight,
    /// Its field and the record of its solve.
    pub solve: Successive,
}

/// One light scene: the weighted sum of the groups' fields and its readouts.
pub struct LightSceneField {
    /// The light scene's name.
    pub name: String,
    /// One per group.
    pub factors: Vec<f64>,
    /// Its field, `Σ_g f_g x_g`, cd/m².
    pub field: Field,
    /// The patches' own emission, cd/m².
    pub emission: Vec<f64>,
    /// The source term `L0`, flat, cd/m².
    pub source: Vec<f64>,
    /// The patches' illuminance and its part direct from the luminaires, lx.
    pub illuminance: Vec<f64>,
    /// The part of `illuminance` direct from the luminaires, lx.
    pub direct_illuminance: Vec<f64>,
    /// Its energy balance, lm.
    pub energy: EnergyBalance,
    /// Its probe readings.
    pub probes: Vec<ProbeReading>,
    /// Its grid readings.
    pub grids: Vec<GridReading>,
    /// Their error bars, one per grid.
    pub grid_errors: Vec<GridErrorBars>,
    /// The UGR at every `[[observer]]` under its dimmed luminaires and its background.
    pub observers: Vec<UgrReading>,
    /// The UGR at every position and view of every `[[glare_grid]]`, likewise.
    pub glare_grids: Vec<GlareGridReading>,
}

impl LightSceneField {
    /// Its observers' and glare grids' readings, which its grids' UGR is taken from.
    pub fn glare(&self) -> GlareReadings<'_> {
        GlareReadings { observers: &self.observers, glare_grids: &self.glare_grids }
    }
}

/// `/light_groups` and `/light_scenes` of `file`, on the patches and cells of `model`.
pub(super) fn write_light_scenes(
    file: &hdf5::File,
    scene: &Scene,
    model: &Model,
    light: &LightScenes,
) -> hdf5::Result<()> {
    let g = file.create_group("light_groups")?;
    write_groups(&g, model, light)?;
    write_factors(&g, &scene.lighting.scenes)?;
    g.new_attr::<f64>().create("maintenance_factor")?.write_scalar(&scene.lighting.maintenance_factor)?;
    write_scenes(&file.create_group("light_scenes")?, &light.scenes, model.mesh.len(), model.kernel.cells())
}

/// `<name>/…` of every light scene in `group` (`/light_scenes`), on `n` patches of `k` cells.
pub(super) fn write_scenes(group: &hdf5::Group, scenes: &[LightSceneField], n: usize, k: usize) -> hdf5::Result<()> {
    scenes.iter().try_for_each(|s| write_scene(&group.create_group(&s.name)?, s, n, k))
}

/// `/light_groups/{scene_names,factors}`: the light scenes and their factors per group.
pub(super) fn write_factors(g: &hdf5::Group, scenes: &[LightScene]) -> hdf5::Result<()> {
    let count = scenes.first().map_or(0, |s| s.factors.len());
    strings(g, "scene_names", scenes.iter().map(|s| s.name.as_str()))?;
    dataset(g, "factors", &Array2::from_shape_fn((scenes.len(), count), |(s, a)| scenes[s].factors[a]))
}

fn write_groups(g: &hdf5::Group, model: &Model, light: &LightScenes) -> hdf5::Result<()> {
    let (n, k, count) = (model.mesh.len(), model.kernel.cells(), light.groups.len());
    strings(g, "name", light.groups.iter().map(|x| x.name.as_str()))?;
    let fields = Array4::from_shape_fn((count, n, k, 1), |(a, i, c, _)| light.groups[a].solve.x[i * k + c]);
    dataset(g, "luminance", &fields)?;
    dataset(g, "emission", &Array2::from_shape_fn((count, n), |(a, i)| light.groups[a].emission[i]))?;
    let direct = Array4::from_shape_fn((count, n, k, 1), |(a, i, c, _)| light.groups[a].direct.arriving[i * k + c]);
    dataset(g, "direct", &direct)?;
    let luminaires = light.groups.first().map_or(0, |x| x.direct.intercepted.len());
    dataset(
        g,
        "intercepted",
        &Array2::from_shape_fn((count, luminaires), |(a, l)| light.groups[a].direct.intercepted[l]),
    )?;
    let column = |f: fn(&Successive) -> f64| Array1::from_iter(light.groups.iter().map(|x| f(&x.solve)));
    dataset(g, "applications", &column(|s| s.applications as f64))?;
    dataset(g, "iterations", &column(|s| s.info.iterations as f64))?;
    dataset(g, "start_residual", &column(|s| s.start))?;
    dataset(g, "residual", &column(|s| s.residual))?;
    dataset(g, "seconds", &column(|s| s.info.seconds))?;
    light.shared.as_ref().map_or(Ok(()), |shared| write_group_readouts(g, shared))
}

/// `/light_groups/grid_readings` (G×P×2: every grid's points in turn, the illuminance and
/// its direct part, lx) and `/light_groups/bar_samples` (G×M×2: `π r` in lx and the albedo
/// of the point seen) of the groups' readouts `shared`; each left out when it is empty (no
/// grid point, no probe or grid).
pub(super) fn write_group_readouts(g: &hdf5::Group, shared: &GroupReadouts) -> hdf5::Result<()> {
    let samples: Vec<Vec<f64>> =
        shared.samples.iter().map(|r| r.0.iter().flat_map(|s| [s.illuminance, s.albedo]).collect()).collect();
    for (name, rows) in [("grid_readings", shared.values()), ("bar_samples", samples)] {
        let Some(m) = rows.first().map(Vec::len).filter(|&m| m > 0) else { continue };
        dataset(g, name, &Array3::from_shape_fn((rows.len(), m / 2, 2), |(a, i, c)| rows[a][2 * i + c]))?;
    }
    Ok(())
}

/// The groups' readouts as a file stores them: per group, its grids' points' illuminance
/// and direct part in turn (lx), and its residual samples.
pub type StoredReadouts = (Vec<Vec<f64>>, Vec<ResidualSamples>);

/// The groups' readouts the solution file `path` stores for `groups` groups, as
/// [`GroupReadouts::stored`] takes them (absent datasets read as no values), or `None`
/// when it stores none or holds values that are not finite.
pub fn read_group_readouts(path: &Path, groups: usize) -> Result<Option<StoredReadouts>, IoError> {
    let (h5, bytes) = super::read::open(path)?;
    let stored = |name: &str| h5.link_exists(&format!("light_groups/{name}"));
    if groups == 0 || !(stored("grid_readings") || stored("bar_samples")) {
        return Ok(None);
    }
    let file = super::read::File { h5: &h5, bytes };
    let why = |super::read::Why(why)| IoError::NotASolution { path: path.to_path_buf(), why };
    let rows = |name: &str| -> Result<Option<Vec<Vec<f64>>>, IoError> {
        let values = match stored(name) {
            true => file.raw::<f64>(&format!("light_groups/{name}")).map_err(why)?,
            false => Vec::new(),
        };
        if values.len() % (2 * groups) != 0 || values.iter().any(|v| !v.is_finite()) {
            return Ok(None);
        }
        let per_group = values.len() / groups;
        Ok(Some((0..groups).map(|g| values[g * per_group..(g + 1) * per_group].to_vec()).collect()))
    };
    let (Some(values), Some(samples)) = (rows("grid_readings")?, rows("bar_samples")?) else { return Ok(None) };
    let row =
        |row: Vec<f64>| ResidualSamples(row.chunks(2).map(|s| Sample { illuminance: s[0], albedo: s[1] }).collect());
    Ok(Some((values, samples.into_iter().map(row).collect())))
}

/// One group's field as a solve stored it (`/light_groups/{name,luminance,direct,intercepted}`).
pub struct StoredGroup {
    /// The group's name.
    pub name: String,
    /// Its field alone, flat `x[i·K + k]`, cd/m².
    pub x: Vec<f64>,
    /// Its luminaires' direct light (`arriving` and `intercepted`; no rays, no `least`), or
    /// `None` in a file solved before it was stored.
    pub direct: Option<DirectLight>,
}

/// The groups' fields of the solution file `path`, each `size` unknowns long, with their
/// direct light on `luminaires` luminaires where the file holds it; none when the case was
/// solved without light scenes.
pub fn read_light_groups(path: &Path, size: usize, luminaires: usize) -> Result<Vec<StoredGroup>, IoError> {
    let (h5, bytes) = super::read::open(path)?;
    if !h5.link_exists("light_groups") {
        return Ok(Vec::new());
    }
    let file = super::read::File { h5: &h5, bytes };
    let why = |super::read::Why(why)| IoError::NotASolution { path: path.to_path_buf(), why };
    let names = file.raw::<VarLenUnicode>("light_groups/name").map_err(why)?;
    let per_group = |what: &str, size: usize| per_group(&file, what, names.len(), size).map_err(why);
    let fields = per_group("luminance", size)?;
    let direct = match h5.link_exists("light_groups/direct") {
        true => Some((per_group("direct", size)?, per_group("intercepted", luminaires)?)),
        false => None,
    };
    let group = |(g, name): (usize, &VarLenUnicode)| StoredGroup {
        name: name.as_str().to_string(),
        x: fields[g].clone(),
        direct: direct.as_ref().map(|(arriving, intercepted)| DirectLight {
            arriving: arriving[g].clone(),
            intercepted: intercepted[g].clone(),
            rays: 0,
            least: Vec::new(),
        }),
    };
    Ok(names.iter().enumerate().map(group).collect())
}

/// `/light_groups/<what>` as `groups` rows of `size` finite values each.
fn per_group(
    file: &super::read::File,
    what: &str,
    groups: usize,
    size: usize,
) -> Result<Vec<Vec<f64>>, super::read::Why> {
    let values = file.raw::<f64>(&format!("light_groups/{what}"))?;
    if values.len() != groups * size {
        let what = format!("/light_groups/{what} holds {} values, expected {groups} groups × {size}", values.len());
        return Err(super::read::Why(what));
    }
    if let Some(i) = values.iter().position(|v| !v.is_finite()) {
        return Err(super::read::Why(format!("/light_groups/{what}[{i}] = {}, not a finite value", values[i])));
    }
    Ok((0..groups).map(|g| values[g * size..(g + 1) * size].to_vec()).collect())
}

fn write_scene(g: &hdf5::Group, s: &LightSceneField, n: usize, k: usize) -> hdf5::Result<()> {
    let field = g.create_group("field")?;
    dataset(&field, "luminance", &s.field.luminance)?;
    let own = ndarray::Array3::from_shape_fn((n, k, 1), |(i, _, _)| s.emission[i]);
    dataset(&field, "emission", &own)?;
    dataset(&field, "source", &ndarray::Array3::from_shape_fn((n, k, 1), |(i, c, _)| s.source[i * k + c]))?;
    dataset(&field, "illuminance", &Array1::from(s.illuminance.clone()))?;
    dataset(&field, "direct_illuminance", &Array1::from(s.direct_illuminance.clone()))?;
    write_probes(&g.create_group("probes")?, &s.probes)?;
    write_observers(&g.create_group("observers")?, &s.observers)?;
    write_glare_grids(&g.create_group("glare_grids")?, &s.glare_grids)?;
    write_grids(&g.create_group("grids")?, &s.grids, &s.grid_errors, s.glare())?;
    g.new_attr::<f64>().shape(s.factors.len()).create("factors")?.write_raw(&s.factors)?;
    let e = &s.energy;
    for (name, value) in [
        ("flux_emitted", e.emitted),
        ("flux_absorbed", e.absorbed),
        ("flux_escaped", e.escaped),
        ("flux_imbalance", e.imbalance),
    ] {
        g.new_attr::<f64>().create(name)?.write_scalar(&value)?;
    }
    Ok(())
}

/// Puts the light scene `name` of the solution file `path` in place of `stored`'s field:
/// its luminance and emission (the reflection orders, which are the case's own light's,
/// are dropped).
pub fn read_light_scene(path: &Path, stored: &mut StoredSolution, name: &str) -> Result<(), IoError> {
    let why = |why: String| IoError::NotASolution { path: path.to_path_buf(), why };
    let file = hdf5::File::open(path).map_err(|e| IoError::Open { path: path.to_path_buf(), why: e.to_string() })?;
    let known = || -> String {
        let names = file.dataset("light_groups/scene_names").and_then(|d| d.read_raw::<VarLenUnicode>());
        match names {
            Ok(names) if !names.is_empty() => {
                names.iter().map(|n| format!("\"{}\"", n.as_str())).collect::<Vec<_>>().join(", ")
            }
            _ => "none (give the case [[light_scene]] tables and solve it again)".to_string(),
        }
    };
    if name.contains('/') || file.group(&format!("light_scenes/{name}")).is_err() {
        return Err(IoError::NoLightScene { path: path.to_path_buf(), name: name.to_string(), known: known() });
    }
    let size = stored.luminance.len();
    let bytes = std::fs::metadata(path).map_err(|e| why(e.to_string()))?.len();
    let read = |what: &str, expected: usize| -> Result<Vec<f64>, IoError> {
        let at = format!("light_scenes/{name}/field/{what}");
        let d = file.dataset(&at).map_err(|e| why(format!("/{at}: {e}")))?;
        if d.size() != expected || (d.size() as u128) * 8 > bytes as u128 {
            return Err(why(format!("/{at} holds {} values, expected {expected}", d.size())));
        }
        let values = d.read_raw::<f64>().map_err(|e| why(format!("/{at}: {e}")))?;
        match values.iter().position(|v| !v.is_finite()) {
            Some(i) => Err(why(format!("/{at}[{i}] = {}, not a finite luminance", values[i]))),
            None => Ok(values),
        }
    };
    let luminance = read("luminance", size)?;
    let emission = read("emission", size)?;
    let k = stored.directions.len();
    stored.mesh.emission = emission.chunks(k).map(|cells| cells[0]).collect();
    stored.luminance = luminance;
    stored.orders.clear();
    Ok(())
}
