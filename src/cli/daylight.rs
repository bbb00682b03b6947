//! The daylight lines of `ugo solve`'s summary: SC, ERC, IRC and DF (%) at every probe, the
//! daylight factor's statistics on every grid (`docs/daylight.md`).

use ugo::readout::daylight::{DaylightReadings, stats};
use ugo::readout::grid::GridReading;
use ugo::readout::probe::ProbeReading;

/// Prints the daylight readouts under `E_h`.
pub fn report(d: &DaylightReadings, probes: &[ProbeReading], grids: &[GridReading]) {
    println!(
        "  daylight           E_h = {:.1} lx (the unobstructed sky, no sun); in % of E_h:",
        d.horizontal_illuminance
    );
    if !probes.is_empty() {
        println!("    probe                      SC %      ERC %      IRC %       DF %");
        for (p, x) in probes.iter().zip(&d.probes) {
            println!(
                "    {:<22} {:>8.3} {:>10.3} {:>10.3} {:>10.3}",
                p.name, x.sky_component, x.externally_reflected, x.internally_reflected, x.daylight_factor
            );
        }
    }
    if !grids.is_empty() {
        println!("    grid                   DF_avg %   DF_min %   DF_max %   DF_min/DF_avg");
        for (g, df) in grids.iter().zip(&d.grids) {
            let st = stats(df, g);
            println!(
                "    {:<22} {:>8.3} {:>10.3} {:>10.3} {:>10.4}",
                g.grid.name, st.average, st.min, st.max, st.uniformity
            );
        }
    }
}
