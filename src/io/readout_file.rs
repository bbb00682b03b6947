//! The file `ugo readout` writes (issue 38, point 2; `docs/light-scenes.md`, "After the
//! solve"): a copy of a solution file whose case, readouts and light scenes are those of
//! the edited case — `/case_files` and the root attributes of the case, `/probes`, `/grids`,
//! `/observers` and `/glare_grids` (when read again; with them `/daylight` when the case is lit by
//! daylight alone), `/light_groups/{scene_names,factors}` and
//! `/light_scenes/<name>` of every new or changed light scene (those no longer in the case
//! dropped, the unchanged ones kept), `/light_groups/{grid_readings,bar_samples}` when light scenes were read
//! (dropped when the readout tables changed and none was) — laid out as `hdf5_file.rs` and `light_scene_group.rs`
//! lay them out for a solve, so that `ugo report` and `ugo render --light-scene` read them
//! alike (`docs/design.md` §8). The field, the groups' fields, the mesh, the kernel and every record of the solve
//! are kept as they were. The copy is written under a temporary name and renamed when
//! complete (`atomic.rs`), so the input is never changed on error, even when it is also
//! the output.

use super::daylight_group::write_daylight;
use super::glare_grid_group::write_glare_grids;
use super::hdf5_file::{CASE_ATTRIBUTES, write_case};
use super::light_scene_group::{write_factors, write_group_readouts, write_scenes};
use super::observer_group::write_observers;
use super::readout_group::{write_grids, write_probes};
use super::{IoError, LightSceneField};
use crate::model::Model;
use crate::readout::daylight::DaylightReadings;
use crate::readout::group_readouts::GroupReadouts;
use crate::readout::readings::Readings;
use crate::scene::Scene;
use std::path::Path;

/// What `ugo readout` computed on a stored field.
pub struct Readout {
    /// The model rebuilt around the stored kernel, lit as the case.
    pub model: Model,
    /// The case's own field read at the edited case's probes, grids and observers; `None`
    /// when they are the stored ones, whose readings are kept.
    pub readings: Option<Readings>,
    /// The daylight factors of `readings` under a `[sky]` when the case is lit by daylight
    /// alone (its field is the daylight's); `None` keeps the stored `/daylight`.
    pub daylight: Option<DaylightReadings>,
    /// Every new or changed light scene of the edited case, a weighted sum of the stored
    /// groups' fields.
    pub light_scenes: Vec<LightSceneField>,
    /// The groups' readouts the new light scenes' grids and bars were read from (stored
    /// or read), when some were read: written as `/light_groups/{grid_readings,bar_samples}`.
    pub shared: Option<GroupReadouts>,
    /// The light scenes kept as stored (their factors and the readout tables unchanged).
    pub kept: Vec<String>,
    /// The groups whose luminaires were traced again (a file without their direct light).
    pub traced: Vec<String>,
}

/// Copies the solution file `input` to `output` (which may be `input`) with the case
/// `scene` and the readouts `readout` in place of the stored ones.
pub fn write_readout(input: &Path, output: &Path, scene: &Scene, readout: &Readout) -> Result<(), IoError> {
    super::atomic(output, |tmp| {
        std::fs::copy(input, tmp).map_err(|e| format!("cannot copy {}: {e}", input.display()))?;
        rewrite(tmp, scene, readout).map_err(|e| e.to_string())
    })
}

fn rewrite(path: &Path, scene: &Scene, r: &Readout) -> hdf5::Result<()> {
    let file = hdf5::File::open_rw(path)?;
    for name in CASE_ATTRIBUTES {
        file.delete_attr(name)?;
    }
    unlink(&file, "case_files")?;
    write_case(&file, scene)?;
    if let Some(readings) = &r.readings {
        ["probes", "observers", "glare_grids", "grids"].into_iter().try_for_each(|name| unlink(&file, name))?;
        write_probes(&file.create_group("probes")?, &readings.probes)?;
        write_observers(&file.create_group("observers")?, &readings.observers)?;
        write_glare_grids(&file.create_group("glare_grids")?, &readings.glare_grids)?;
        write_grids(&file.create_group("grids")?, &readings.grids, &readings.grid_errors, readings.glare())?;
        if let Some(daylight) = &r.daylight {
            unlink(&file, "daylight")?;
            write_daylight(&file.create_group("daylight")?, daylight, &readings.probes, &readings.grids)?;
        }
    }
    if !file.link_exists("light_groups") {
        unlink(&file, "light_scenes")?;
        return file.close();
    }
    let groups = file.group("light_groups")?;
    groups.unlink("scene_names")?;
    groups.unlink("factors")?;
    write_factors(&groups, &scene.lighting.scenes)?;
    if r.shared.is_some() || r.readings.is_some() {
        ["grid_readings", "bar_samples"].into_iter().try_for_each(|name| unlink(&groups, name))?;
    }
    if let Some(shared) = &r.shared {
        write_group_readouts(&groups, shared)?;
    }
    let scenes = match file.link_exists("light_scenes") {
        true => file.group("light_scenes")?,
        false => file.create_group("light_scenes")?,
    };
    for name in scenes.member_names()? {
        if !r.kept.contains(&name) {
            scenes.unlink(&name)?;
        }
    }
    write_scenes(&scenes, &r.light_scenes, r.model.mesh.len(), r.model.kernel.cells())?;
    file.close()
}

/// Removes `name` from `file` when it is there.
fn unlink(file: &hdf5::Group, name: &str) -> hdf5::Result<()> {
    match file.link_exists(name) {
        true => file.unlink(name),
        false => Ok(()),
    }
}
