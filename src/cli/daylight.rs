//! The daylight lines of `ugo solve`'s summary: SC, ERC, IRC and DF (%) at every probe, the
//! daylight factor's statistics on every grid (`docs/daylight.md`); under a sky that
//! depends on the sun, or with the sun, `E / E_h` is the daylight ratio DR and is labelled so.

use ugo::readout::daylight::{DaylightReadings, stats};
use ugo::readout::grid::GridReading;
use ugo::readout::probe::ProbeReading;

/// Prints the daylight readouts under `E_h`.
pub fn report(d: &DaylightReadings, probes: &[ProbeReading], grids: &[GridReading]) {
    let x = d.symbol();
    say!(
        "  daylight           E_h = {:.1} lx (the unobstructed sky, no sun); in % of E_h, {x} the {}:",
        d.horizontal_illuminance,
        d.quantity()
    );
    if !d.factor {
        say!("    (this sky depends on the sun, or the sun shines: E/E_h is not the daylight factor)");
    }
    if !probes.is_empty() {
        say!("    probe                      SC %      ERC %      IRC %       {x} %");
        for (p, y) in probes.iter().zip(&d.probes) {
            say!(
                "    {:<22} {:>8.3} {:>10.3} {:>10.3} {:>10.3}",
                p.name,
                y.sky_component,
                y.externally_reflected,
                y.internally_reflected,
                y.daylight_factor
            );
        }
    }
    if !grids.is_empty() {
        say!("    grid                   {x}_avg %   {x}_min %   {x}_max %   {x}_min/{x}_avg");
        for (i, g) in grids.iter().enumerate() {
            let st = stats(&d.grid_factor(i), g);
            say!(
                "    {:<22} {:>8.3} {:>10.3} {:>10.3} {:>10.4}",
                g.grid.name,
                st.average,
                st.min,
                st.max,
                st.uniformity
            );
        }
    }
}
