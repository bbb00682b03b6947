//! A `[[glare_grid]]`'s CSV (`docs/photometry.md`, "UGR on a grid of observers"): one row
//! per eye position and view, `u,v,x,y,z,turn_deg,look_x,look_y,look_z,UGR,L_b_cd_m2,sources,outside_validity`
//! (`u`, `v` the position's cell indices; `UGR` `-inf` where no luminaire is seen;
//! `outside_validity` the luminaires counted whose solid angle is outside CIE 117's range),
//! the largest UGR and the limit in `#` comments.

use super::IoError;
use crate::readout::glare_grid::GlareGridReading;
use std::path::Path;

/// Writes `reading` to `path` through a temporary file.
pub fn write_glare_grid_csv(path: &Path, reading: &GlareGridReading) -> Result<(), IoError> {
    let grid = &reading.grid;
    let ([nu, _], views) = (grid.resolution, grid.views.len());
    let largest = reading.largest();
    let limit = grid.ugr_limit.map_or("no ugr_limit".to_string(), |l| format!("ugr_limit {l}"));
    let mut text = format!(
        "# glare grid \"{}\": UGR of CIE 117 at {} positions × {views} views\n\
         # UGR_max {:.4} at u {}, v {}, turn {}°; {limit}\n\
         u,v,x,y,z,turn_deg,look_x,look_y,look_z,UGR,L_b_cd_m2,sources,outside_validity\n",
        grid.name,
        reading.readings.len() / views,
        largest.ugr,
        largest.position % nu,
        largest.position / nu,
        grid.views[largest.view].turn_deg
    );
    for (k, r) in reading.readings.iter().enumerate() {
        let (i, view) = (k / views, &grid.views[k % views]);
        let (p, l) = (r.observer.position, view.look);
        text += &format!(
            "{},{},{:.9},{:.9},{:.9},{},{:.9},{:.9},{:.9},{:.6},{:.6e},{},{}\n",
            i % nu,
            i / nu,
            p.x,
            p.y,
            p.z,
            view.turn_deg,
            l.x,
            l.y,
            l.z,
            r.ugr(),
            r.background,
            r.sources.len(),
            r.outside_validity()
        );
    }
    super::write_bytes(path, text.as_bytes())
}
