//! The file `ugo readout` writes (issue 38, point 2; `docs/light-scenes.md`, "After the
//! solve"): a copy of a solution file whose case, readouts and light scenes are replaced
//! by those of the edited case — `/case_files` and the root attributes of the case,
//! `/probes`, `/grids`, `/observers`, `/light_groups/{scene_names,factors}` and
//! `/light_scenes` — laid out as `hdf5_file.rs` and `light_scene_group.rs` lay them out
//! for a solve, so that `ugo report` and `ugo render --light-scene` read them alike. The
//! field, the groups' fields, the mesh, the kernel and every record of the solve are kept as
//! they were. The copy is written under a temporary name and renamed when complete
//! (`atomic.rs`), so the input is never changed on error, even when it is also the output.

use super::hdf5_file::{CASE_ATTRIBUTES, write_case};
use super::light_scene_group::{write_factors, write_scenes};
use super::observer_group::write_observers;
use super::readout_group::{write_grids, write_probes};
use super::{IoError, LightSceneField};
use crate::model::Model;
use crate::readout::readings::Readings;
use crate::scene::Scene;
use std::path::Path;

/// What `ugo readout` computed on a stored field.
pub struct Readout {
    /// The model rebuilt around the stored kernel, lit as the case.
    pub model: Model,
    /// The case's own field read at the edited case's probes, grids and observers.
    pub readings: Readings,
    /// Every light scene of the edited case, a weighted sum of the stored groups' fields.
    pub light_scenes: Vec<LightSceneField>,
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
    for name in ["case_files", "probes", "observers", "grids", "light_scenes"] {
        if file.link_exists(name) {
            file.unlink(name)?;
        }
    }
    write_case(&file, scene)?;
    write_probes(&file.create_group("probes")?, &r.readings.probes)?;
    write_observers(&file.create_group("observers")?, &r.readings.observers)?;
    write_grids(&file.create_group("grids")?, &r.readings.grids, &r.readings.grid_errors, &r.readings.observers)?;
    if file.link_exists("light_groups") {
        let groups = file.group("light_groups")?;
        groups.unlink("scene_names")?;
        groups.unlink("factors")?;
        write_factors(&groups, &r.light_scenes)?;
        write_scenes(&file, &r.light_scenes, r.model.mesh.len(), r.model.kernel.cells())?;
    }
    file.close()
}
