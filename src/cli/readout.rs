//! `ugo readout OUT.h5 [CASE] [-o NEW.h5]`: probes, grids, observers, cameras and light
//! scenes of an edited case read on the field a solve stored (`ugo::study::read_out_solved`,
//! `docs/light-scenes.md`, "After the solve: ugo readout"): no assembly, no refinement, no
//! solve; only what the edit changed is read. Without `-o` the solution file itself is
//! replaced, whole, when the new one is complete; the CSV and plan files of what was read
//! are written beside the output as `ugo solve` writes them (those of what was kept stay
//! where the solve wrote them).

use super::options::Discretize;
use super::solve::{GridFiles, print_probes, write_grids};
use super::{Bars, check_writable, load};
use anyhow::{Context, Result};
use std::path::{Path, PathBuf};
use std::time::Instant;
use ugo::io::{OutputLock, read_solution, write_probes_csv, write_readout};
use ugo::readout::daylight::DaylightReadings;
use ugo::readout::grid::GridReading;
use ugo::readout::grid_error::GridErrorBars;
use ugo::readout::readings::Readings;
use ugo::scene::{LightScene, Scene};
use ugo::study;

pub fn run(file: &Path, case: Option<&Path>, d: &Discretize, output: Option<PathBuf>) -> Result<()> {
    let output = output.unwrap_or_else(|| file.to_path_buf());
    check_writable(&output)?;
    let _lock = OutputLock::take(&output)?;
    let scene = match case {
        Some(case) => load(case, d)?,
        None => stored_case(file, d)?,
    };
    let start = Instant::now();
    let r =
        study::read_out_solved(file, &scene, &Bars::default()).map_err(|e| super::stop::not_written(e, &[&output]))?;
    let seconds = start.elapsed().as_secs_f64();
    write_readout(file, &output, &scene, &r).with_context(|| format!("writing {}", output.display()))?;
    say!("ugo readout: {} read on the field of {} in {seconds:.3} s", scene.path.display(), file.display());
    if !r.traced.is_empty() {
        let groups = r.traced.join(", ");
        say!("  note: {} holds no /light_groups/direct (an older solve): traced again {groups}", file.display());
    }
    let names: Vec<String> = scene.surfaces.iter().map(|s| s.name.clone()).collect();
    let files = GridFiles { sources: &r.model.sources, mesh: &r.model.mesh, surfaces: &names };
    match &r.readings {
        Some(readings) => own_readings(readings, r.daylight.as_ref(), &output, &files)?,
        None => say!("  probes, grids, glare grids and observers as stored (unchanged)"),
    }
    let lit = |grids: &[GridReading], errors: &[GridErrorBars], stem: &str, light_scene: &LightScene| {
        let dimmed = study::dimmed(&scene, &r.model.sources, light_scene);
        write_grids(grids, errors, stem, &GridFiles { sources: &dimmed, ..files }, None)
    };
    let groups: Vec<&str> = scene.lighting.groups.iter().map(|g| g.name.as_str()).collect();
    let read: Vec<LightScene> = scene.lighting.scenes.iter().filter(|s| !r.kept.contains(&s.name)).cloned().collect();
    super::light_scenes::report_scenes(&groups, &r.light_scenes, &read, &output, &lit)?;
    for name in &r.kept {
        say!("  light scene \"{name}\" as stored (its factors and the readout tables unchanged)");
    }
    say!("  written            {}", output.display());
    Ok(())
}

/// Prints the case's own field's readings (with their daylight factors, `daylight`) and
/// writes their files beside `output`.
fn own_readings(
    readings: &Readings,
    daylight: Option<&DaylightReadings>,
    output: &Path,
    files: &GridFiles,
) -> Result<()> {
    print_probes(&readings.probes);
    super::glare::report(readings.glare(), &readings.grids, "  ");
    if let Some(d) = daylight {
        super::daylight::report(d, &readings.probes, &readings.grids);
    }
    let stem = output.with_extension("").display().to_string();
    write_grids(&readings.grids, &readings.grid_errors, &stem, files, daylight)?;
    if !readings.probes.is_empty() {
        let csv = super::beside(output, "-probes.csv");
        write_probes_csv(&csv, &readings.probes, daylight)?;
        say!("  probes             {}", csv.display());
    }
    super::glare_grid::report(&readings.glare_grids, output, "  ")
}

/// The case stored in the solution file, with the command line's discretization flags.
fn stored_case(file: &Path, d: &Discretize) -> Result<Scene> {
    let mut scene = read_solution(file)?.scene;
    scene.discretize(&d.asked())?;
    Ok(scene)
}
