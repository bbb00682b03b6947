//! Readouts and light scenes after the solve (issue 38, point 2; `docs/light-scenes.md`,
//! "After the solve: ugo readout"). The model is rebuilt around the kernel a solve saved
//! (`super::kernel`: no assembly, no refinement) for the edited case, which must be the
//! solved one in everything the field depends on: its geometry and discretization (the
//! kernel file's fingerprint), its reflectances and luminaires, its surfaces' emission and
//! its groups of sources. Then, with no solve, only what the edit changed is read: the
//! stored field `x` at the case's probes, grids, observers and glare grids when they are not the stored
//! ones, and every new or changed light scene as `x_s = Σ_g f_{s,g} x_g`
//! (`docs/design.md` §1: the field is linear in its sources) of the stored groups' fields,
//! read out as the solve reads it (`super::light_scenes::read_light_scenes`) with each
//! group's stored direct light (`super::group_light`), its grid readings and error bars
//! from the groups' readouts the file stores (`/light_groups/{grid_readings,bar_samples}`,
//! `readout::group_readouts`), read here (every group's, once) when the file holds none
//! for these probes and grids.
//! A light scene whose factors and readout tables are the stored ones keeps its stored
//! readings. Under a `[sky]`, new probes or grids get their daylight factors when the case
//! is lit by daylight alone (its field is the daylight's, `super::daylight_alone`); with other
//! light they would need the daylight solved alone, and are refused.

use super::daylight_alone::lit_by_daylight_alone;
use super::error::StudyError;
use super::group_light::stored_group_terms;
use super::kernel::model_with_kernel;
use super::light_scenes::read_light_scenes;
use super::readout_error::ReadoutError;
use crate::io::{Readout, StoredGroup, read_group_readouts, read_light_groups, read_solution};
use crate::model::Model;
use crate::progress::Progress;
use crate::readout::daylight::read_daylight;
use crate::readout::field::Field;
use crate::readout::group_readouts::GroupReadouts;
use crate::readout::readings::read_field;
use crate::scene::{LightScene, Scene};
use std::path::Path;

/// The readouts of `scene` on the field stored in the solution file `file`: those the
/// edit changed; the others are kept as stored (`Readout::readings`, `Readout::kept`).
pub fn read_out_solved(file: &Path, scene: &Scene, progress: &dyn Progress) -> Result<Readout, StudyError> {
    let (mut model, record) = model_with_kernel(scene, Some(file), false, progress)?;
    let paths = || (scene.path.clone(), file.to_path_buf());
    if let Some(loaded) = record.loaded.filter(|l| !l.rebuilt.is_empty()) {
        let (case, file) = paths();
        return Err(ReadoutError::Changed { case, file, changes: loaded.rebuilt }.into());
    }
    let stored = read_solution(file)?;
    same_emission(scene, &model, &stored.mesh.emission, file)?;
    let (probes, grids) = (scene.probes == stored.scene.probes, scene.grids == stored.scene.grids);
    let daylight_alone = lit_by_daylight_alone(scene, &model);
    if scene.sky.is_some() && !(probes && grids) && !daylight_alone {
        let (case, file) = paths();
        return Err(ReadoutError::Daylight { case, file }.into());
    }
    let same_tables =
        probes && grids && scene.observers == stored.scene.observers && scene.glare_grids == stored.scene.glare_grids;
    let x = stored.luminance;
    let k = model.kernel.cells();
    let readings = (!same_tables).then(|| read_field(scene, &model, &Field::from_unknowns(&x, k), progress));
    // Lit by daylight alone, the field read is the daylight's: its factors are read on it.
    let daylight = match (&readings, &scene.sky) {
        (Some(r), Some(sky)) if daylight_alone => Some(read_daylight(&model, sky, &r.probes, &r.grids)),
        _ => None,
    };
    let (kept, read): (Vec<&LightScene>, Vec<&LightScene>) =
        scene.lighting.scenes.iter().partition(|s| same_tables && stored.scene.lighting.scenes.contains(s));
    let groups = read_light_groups(file, x.len(), model.sources.len())?;
    if !scene.lighting.scenes.is_empty() {
        same_groups(scene, &stored.scene, &groups, file)?;
    }
    let stored = match probes && grids {
        true => read_group_readouts(file, groups.len())?,
        false => None,
    };
    let stored = stored.and_then(|(values, samples)| GroupReadouts::stored(&scene.grids, &model, values, samples));
    let (light_scenes, shared, traced) = match read.is_empty() {
        true => (Vec::new(), None, Vec::new()),
        false => {
            let xs: Vec<&[f64]> = groups.iter().map(|g| g.x.as_slice()).collect();
            let every = stored.is_none();
            let lit = |g: usize| every || read.iter().any(|s| s.factors[g] != 0.0);
            let (terms, traced) = stored_group_terms(scene, &model, &groups, lit);
            let (scenes, shared) = read_light_scenes(scene, &mut model, &terms, &xs, &read, stored, progress)?;
            (scenes, shared, traced)
        }
    };
    let kept = kept.into_iter().map(|s| s.name.clone()).collect();
    Ok(Readout { model, readings, daylight, light_scenes, shared, kept, traced })
}

/// Refuses a case whose surfaces emit otherwise than the solved ones (`stored`, per patch).
fn same_emission(scene: &Scene, model: &Model, stored: &[f64], file: &Path) -> Result<(), ReadoutError> {
    let case = &model.mesh.emission;
    let Some(patch) = (0..case.len()).find(|&i| stored.get(i) != Some(&case[i])) else { return Ok(()) };
    let surface = model.mesh.patches[patch].surface as usize;
    Err(ReadoutError::Emission {
        case: scene.path.clone(),
        file: file.to_path_buf(),
        surface: scene.surfaces.get(surface).map_or_else(|| format!("#{surface}"), |s| s.name.clone()),
        patch,
        case_value: case[patch],
        stored: stored.get(patch).copied().unwrap_or(f64::NAN),
    })
}

/// Refuses a light scene that lights a group the file does not hold, and groups of sources
/// other than the solved case's (`solved`, whose fields are `groups`).
fn same_groups(scene: &Scene, solved: &Scene, groups: &[StoredGroup], file: &Path) -> Result<(), ReadoutError> {
    let held = |name: &str| groups.iter().any(|g| g.name == name);
    for light_scene in &scene.lighting.scenes {
        let lit = scene.lighting.groups.iter().zip(&light_scene.factors).filter(|(_, f)| **f != 0.0);
        if let Some(group) = lit.map(|(g, _)| g).find(|g| !held(&g.name)) {
            return Err(ReadoutError::AbsentGroup {
                case: scene.path.clone(),
                file: file.to_path_buf(),
                scene: light_scene.name.clone(),
                group: group.name.clone(),
                present: groups.iter().map(|g| format!("\"{}\"", g.name)).collect(),
            });
        }
    }
    let (ours, theirs) = (&scene.lighting.groups, &solved.lighting.groups);
    let differs = (0..ours.len().max(theirs.len())).find(|&i| ours.get(i) != theirs.get(i));
    match differs {
        None => Ok(()),
        Some(i) => Err(ReadoutError::OtherGroup {
            case: scene.path.clone(),
            file: file.to_path_buf(),
            group: ours.get(i).or(theirs.get(i)).map_or_else(String::new, |g| g.name.clone()),
        }),
    }
}
