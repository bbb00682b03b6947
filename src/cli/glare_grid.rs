//! The glare grids' block of `ugo solve`'s and `ugo readout`'s summary
//! (`docs/photometry.md`, "UGR on a grid of observers"): per `[[glare_grid]]` its positions
//! and views, the largest UGR and where, the positions above its `ugr_limit` and the check
//! against it, the CSV `<stem>-glare-<name>.csv` written beside the solution file, and a
//! warning on stderr when sources are outside the formula's solid angles.

use super::glare::{against, shown, warn_outside};
use anyhow::Result;
use std::path::Path;
use ugo::io::write_glare_grid_csv;
use ugo::readout::glare_grid::GlareGridReading;

/// Prints a block per glare grid, each line after `indent` (a light scene's block is
/// indented further), and writes its CSV beside `output`.
pub fn report(readings: &[GlareGridReading], output: &Path, indent: &str) -> Result<()> {
    if readings.is_empty() {
        return Ok(());
    }
    say!("{indent}glare grids              positions × views   UGR_max   at (u, v, turn)   above UGR_L   UGR_L");
    for r in readings {
        let (grid, largest) = (&r.grid, r.largest());
        let [nu, nv] = grid.resolution;
        let at =
            format!("({}, {}, {}°)", largest.position % nu, largest.position / nu, grid.views[largest.view].turn_deg);
        let above = grid.ugr_limit.map_or("-".to_string(), |l| {
            format!("{} of {}", r.per_position().iter().filter(|&&u| u > l).count(), nu * nv)
        });
        let size = format!("{nu} × {nv} × {}", grid.views.len());
        let limit = against(largest.ugr, grid.ugr_limit);
        say!("{indent}  {:<22} {size:>18} {:>9} {at:>17} {above:>13}   {limit}", grid.name, shown(largest.ugr));
        let csv = super::beside(output, &format!("-glare-{}.csv", super::file_name(&grid.name)));
        write_glare_grid_csv(&csv, r)?;
        say!("{indent}    {}", csv.display());
        let outside = r.outside_validity();
        if outside > 0 {
            let what = format!("at {outside} of its {} positions and views a luminaire subtends", r.readings.len());
            warn_outside(&format!("glare grid \"{}\"", grid.name), &what);
        }
    }
    Ok(())
}
