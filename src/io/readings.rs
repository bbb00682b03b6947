//! The lighting-engineering tables of a solve: for an illuminance grid (`[[grid]]`) a CSV
//! of every calculation point with its illuminance and its error bar in lx (its plan is `super::grid_map`);
//! for the probes a CSV of their luminance and illuminance (and kind).

use super::IoError;
use crate::readout::daylight::DaylightReadings;
use crate::readout::grid::GridReading;
use crate::readout::grid_error::GridErrorBars;
use crate::readout::probe::ProbeReading;
use std::path::Path;

/// `u,v,x,y,z,E_lx,E_error_lx,counted,left_out_by` per point (`u`, `v` the cell indices;
/// `E_error_lx` the illuminance's error bar of `errors`, empty for a point left out;
/// `counted` 1 for a point in the statistics, 0 for one left out, `left_out_by` then saying
/// what stands over it), statistics with their error bars in `#` comments; under a `[sky]`
/// (`daylight`: the symbol `DF` or `DR` and one value per point, %) a last column `DF_pct`
/// (or `DR_pct`).
pub fn write_grid_csv(
    path: &Path,
    grid: &GridReading,
    errors: &GridErrorBars,
    surfaces: &[String],
    daylight: Option<(&str, &[f64])>,
) -> Result<(), IoError> {
    let [nu, _] = grid.grid.resolution;
    let st = grid.stats();
    let mut text = format!(
        "# grid \"{}\", illuminance in lx on the side facing {:?}\n\
         # E_avg {:.6e} ± {:.3e}, E_min {:.6e} ± {:.3e}, E_max {:.6e}, U0 {:.6} ± {:.6} over the {} of {} points counted\n\
         u,v,x,y,z,E_lx,E_error_lx,counted,left_out_by{}\n",
        grid.grid.name,
        grid.grid.normal.to_array(),
        st.average,
        errors.average,
        st.min,
        errors.min,
        st.max,
        st.u0,
        errors.u0,
        st.counted,
        grid.points.len(),
        daylight.map_or(String::new(), |(x, _)| format!(",{x}_pct"))
    );
    for (i, ((p, e), o)) in grid.points.iter().zip(&grid.illuminance).zip(&grid.obstructed).enumerate() {
        let by = o.as_ref().map_or(String::new(), |o| {
            let name = surfaces[o.surface].replace('"', "\"\"");
            if o.inside { format!("inside {name}") } else { format!("{:.3} m under {name}", o.distance) }
        });
        text += &format!(
            "{},{},{:.9},{:.9},{:.9},{:.9e},{},{},\"{by}\"{}\n",
            i % nu,
            i / nu,
            p.x,
            p.y,
            p.z,
            e,
            Some(errors.points[i]).filter(|d| !d.is_nan()).map_or(String::new(), |d| format!("{d:.3e}")),
            u8::from(o.is_none()),
            daylight.map_or(String::new(), |(_, df)| format!(",{:.9e}", df[i]))
        );
    }
    write_text(path, &text)
}

/// `name,x,y,z,nx,ny,nz,L_cd_m2,E_lx,E_direct_lx,E_correction_lx,E_error_lx,kind`
/// per probe (`E_direct_lx`: the luminaires' part; `E_correction_lx`: the correction near
/// geometry included in `E_lx`; `E_error_lx`: its error bar, empty where none was
/// estimated; `kind` as in the case, e.g. `cylindrical`, whose `E_lx` is `E_z`); under a
/// `[sky]` then `SC_pct,ERC_pct,IRC_pct,DF_pct` (`DR_pct` for the daylight ratio), % of `E_h`.
pub fn write_probes_csv(
    path: &Path,
    probes: &[ProbeReading],
    daylight: Option<&DaylightReadings>,
) -> Result<(), IoError> {
    let mut text = String::from("name,x,y,z,nx,ny,nz,L_cd_m2,E_lx,E_direct_lx,E_correction_lx,E_error_lx,kind");
    if let Some(d) = daylight {
        text += &format!(",SC_pct,ERC_pct,IRC_pct,{}_pct", d.symbol());
    }
    text.push('\n');
    for (i, p) in probes.iter().enumerate() {
        let (x, n) = (p.position, p.normal);
        let name = p.name.replace('"', "\"\"");
        text += &format!(
            "\"{name}\",{:.9},{:.9},{:.9},{:.9},{:.9},{:.9},{:.9e},{:.9e},{:.9e},{:.9e},{},{}",
            x.x,
            x.y,
            x.z,
            n.x,
            n.y,
            n.z,
            p.luminance,
            p.illuminance,
            p.direct,
            p.correction,
            p.error.map_or(String::new(), |e| format!("{e:.3e}")),
            p.kind.name()
        );
        if let Some(x) = daylight.map(|d| d.probes[i]) {
            text += &format!(
                ",{:.9e},{:.9e},{:.9e},{:.9e}",
                x.sky_component, x.externally_reflected, x.internally_reflected, x.daylight_factor
            );
        }
        text.push('\n');
    }
    write_text(path, &text)
}

fn write_text(path: &Path, text: &str) -> Result<(), IoError> {
    super::write_bytes(path, text.as_bytes())
}
