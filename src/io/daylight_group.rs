//! `/daylight` (`docs/daylight.md`): under a `[sky]`, the sky component, the externally and
//! internally reflected components and the daylight factor at every probe
//! (`/daylight/probes/{name,sky_component,externally_reflected,internally_reflected,daylight_factor}`,
//! %) and on every grid (`/daylight/grids/<name>/{sky_component,externally_reflected,
//! internally_reflected,daylight_factor}`, `nv × nu`, %, with `DF_avg`, `DF_min`, `DF_max` and `uniformity` as attributes); the
//! attribute `E_h` (lx) is the unobstructed sky's horizontal illuminance they are shares of,
//! the attribute `quantity` says whether `E / E_h` is the `"daylight factor"` or the
//! `"daylight ratio"` (a sky that depends on the sun, or the sun shining; the datasets keep
//! the name `daylight_factor`).

use super::dataset::{dataset, strings, text_attr};
use crate::readout::daylight::{Daylight, DaylightReadings, stats};
use crate::readout::grid::GridReading;
use crate::readout::probe::ProbeReading;
use ndarray::{Array1, Array2};

pub(super) fn write_daylight(
    g: &hdf5::Group,
    d: &DaylightReadings,
    probes: &[ProbeReading],
    grids: &[GridReading],
) -> hdf5::Result<()> {
    g.new_attr::<f64>().create("E_h")?.write_scalar(&d.horizontal_illuminance)?;
    text_attr(g, "quantity", d.quantity())?;
    let p = g.create_group("probes")?;
    strings(&p, "name", probes.iter().map(|r| r.name.as_str()))?;
    let column = |f: fn(&Daylight) -> f64| Array1::from_iter(d.probes.iter().map(f));
    dataset(&p, "sky_component", &column(|x| x.sky_component))?;
    dataset(&p, "externally_reflected", &column(|x| x.externally_reflected))?;
    dataset(&p, "internally_reflected", &column(|x| x.internally_reflected))?;
    dataset(&p, "daylight_factor", &column(|x| x.daylight_factor))?;
    let all = g.create_group("grids")?;
    for (i, grid) in grids.iter().enumerate() {
        let h = all.create_group(&grid.grid.name)?;
        let [nu, nv] = grid.grid.resolution;
        let map = |f: fn(&Daylight) -> f64| Array2::from_shape_fn((nv, nu), |(b, a)| f(&d.grids[i][b * nu + a]));
        dataset(&h, "sky_component", &map(|x| x.sky_component))?;
        dataset(&h, "externally_reflected", &map(|x| x.externally_reflected))?;
        dataset(&h, "internally_reflected", &map(|x| x.internally_reflected))?;
        dataset(&h, "daylight_factor", &map(|x| x.daylight_factor))?;
        let st = stats(&d.grid_factor(i), grid);
        for (name, value) in
            [("DF_avg", st.average), ("DF_min", st.min), ("DF_max", st.max), ("uniformity", st.uniformity)]
        {
            h.new_attr::<f64>().create(name)?.write_scalar(&value)?;
        }
    }
    Ok(())
}
