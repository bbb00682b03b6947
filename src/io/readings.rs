//! The lighting-engineering tables of a solve: for an illuminance grid (`[[grid]]`) a CSV
//! of every calculation point with its illuminance in lx (its plan is `super::grid_map`);
//! for the probes a CSV of their luminance and illuminance (and kind).

use super::IoError;
use crate::readout::grid::GridReading;
use crate::readout::probe::ProbeReading;
use std::path::Path;

/// `u,v,x,y,z,E_lx,counted,left_out_by` per point (`u`, `v` the cell indices; `counted` 1
/// for a point in the statistics, 0 for one left out, `left_out_by` then saying what
/// stands over it), statistics in `#` comments.
pub fn write_grid_csv(path: &Path, grid: &GridReading, surfaces: &[String]) -> Result<(), IoError> {
    let [nu, _] = grid.grid.resolution;
    let st = grid.stats();
    let mut text = format!(
        "# grid \"{}\", illuminance in lx on the side facing {:?}\n\
         # E_avg {:.6e}, E_min {:.6e}, E_max {:.6e}, U0 {:.6} over the {} of {} points counted\n\
         u,v,x,y,z,E_lx,counted,left_out_by\n",
        grid.grid.name,
        grid.grid.normal.to_array(),
        st.average,
        st.min,
        st.max,
        st.u0,
        st.counted,
        grid.points.len()
    );
    for (i, ((p, e), o)) in grid.points.iter().zip(&grid.illuminance).zip(&grid.obstructed).enumerate() {
        let by = o.as_ref().map_or(String::new(), |o| {
            let name = surfaces[o.surface].replace('"', "\"\"");
            if o.inside { format!("inside {name}") } else { format!("{:.3} m under {name}", o.distance) }
        });
        text += &format!(
            "{},{},{:.9},{:.9},{:.9},{:.9e},{},\"{by}\"\n",
            i % nu,
            i / nu,
            p.x,
            p.y,
            p.z,
            e,
            u8::from(o.is_none())
        );
    }
    write_text(path, &text)
}

/// `name,x,y,z,nx,ny,nz,L_cd_m2,E_lx,E_direct_lx,E_correction_lx,kind`
/// per probe (`E_direct_lx`: the luminaires' part; `E_correction_lx`: the correction near
/// geometry included in `E_lx`; `kind` as in the
/// case, e.g. `cylindrical`, whose `E_lx` is `E_z`).
pub fn write_probes_csv(path: &Path, probes: &[ProbeReading]) -> Result<(), IoError> {
    let mut text = String::from("name,x,y,z,nx,ny,nz,L_cd_m2,E_lx,E_direct_lx,E_correction_lx,kind\n");
    for p in probes {
        let (x, n) = (p.position, p.normal);
        let name = p.name.replace('"', "\"\"");
        text += &format!(
            "\"{name}\",{:.9},{:.9},{:.9},{:.9},{:.9},{:.9},{:.9e},{:.9e},{:.9e},{:.9e},{}\n",
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
            p.kind.name()
        );
    }
    write_text(path, &text)
}

fn write_text(path: &Path, text: &str) -> Result<(), IoError> {
    super::write_bytes(path, text.as_bytes())
}
