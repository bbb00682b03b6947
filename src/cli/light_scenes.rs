//! The light scenes of a solved case (`[[light_scene]]`, solved by `study::solve_case`
//! after the case's own field): a line per group and a table per light scene, and each
//! light scene's files beside the output: `<stem>-<scene>-probes.csv` and
//! `<stem>-<scene>-<grid>.{csv,png}`.

use anyhow::Result;
use std::path::{Path, PathBuf};
use ugo::io::{LightSceneField, LightScenes, write_probes_csv};
use ugo::readout::grid::GridReading;
use ugo::readout::grid_error::GridErrorBars;
use ugo::scene::LightScene;

/// Writes a light scene's grids' files: its grids, their error bars, the stem of their
/// names, the light scene.
pub type WriteGrids<'a> = dyn Fn(&[GridReading], &[GridErrorBars], &str, &LightScene) -> Result<()> + 'a;

/// Prints the groups' solves and every light scene, and writes its CSV files and, with
/// `write_grids` (the solve's: grids, their error bars, the stem of their files and the light scene of
/// `light_scenes`, the case's, whose dimmed luminaires the plans draw), its grids' files.
pub fn report(light: &LightScenes, light_scenes: &[LightScene], output: &Path, write_grids: &WriteGrids) -> Result<()> {
    say!("  light groups             applications   start residual   residual      time s");
    for g in &light.groups {
        let s = &g.solve;
        say!(
            "    {:<22} {:>12} {:>16.2e} {:>10.2e} {:>11.3}",
            g.name,
            s.applications,
            s.start,
            s.residual,
            s.info.seconds
        );
    }
    let groups: Vec<&str> = light.groups.iter().map(|g| g.name.as_str()).collect();
    report_scenes(&groups, &light.scenes, light_scenes, output, write_grids)
}

/// Prints every light scene (`scenes`, with factors for `groups`), and writes its files as
/// [`report`] does; shared with `ugo readout`.
pub fn report_scenes(
    groups: &[&str],
    scenes: &[LightSceneField],
    light_scenes: &[LightScene],
    output: &Path,
    write_grids: &WriteGrids,
) -> Result<()> {
    let stem = output.with_extension("").display().to_string();
    for (scene, described) in scenes.iter().zip(light_scenes) {
        let factors: Vec<String> = groups.iter().zip(&scene.factors).map(|(g, f)| format!("{g} {f}")).collect();
        let e = &scene.energy;
        say!("  light scene \"{}\"   ({})", scene.name, factors.join(", "));
        say!(
            "    flux emitted {:.4} lm, absorbed {:.4} lm, escaped {:.4} lm, imbalance {:.3e} lm",
            e.emitted,
            e.absorbed,
            e.escaped,
            e.imbalance
        );
        let base = format!("{stem}-{}", scene.name);
        if !scene.probes.is_empty() {
            say!("    probes                 luminance cd/m²   illuminance lx   of it direct lx");
            for p in &scene.probes {
                say!("      {:<20} {:>15.4} {:>16.4} {:>17.4}", p.name, p.luminance, p.illuminance, p.direct);
            }
            let csv = PathBuf::from(format!("{base}-probes.csv"));
            write_probes_csv(&csv, &scene.probes, None)?;
            say!("      {}", csv.display());
        }
        super::glare::report(scene.glare(), &scene.grids, "    ");
        super::glare_grid::report(&scene.glare_grids, &PathBuf::from(format!("{base}.h5")), "    ")?;
        write_grids(&scene.grids, &scene.grid_errors, &base, described)?;
    }
    Ok(())
}
