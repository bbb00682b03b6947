//! `ugo report OUT.h5` (`docs/report.md`): one self-contained HTML page of a solved case,
//! read from its solution file alone (the stored scene, `/grids`, `/luminaires`,
//! `/observers`, `/glare_grids`, `/light_scenes`, `/daylight`, `/field`, `/warnings`; `docs/design.md`
//! §8): materials, luminaires, every grid against its EN 12464-1 targets with its plan
//! (drawn by `grid_map.rs`, embedded as a `data:` URI), glare at the observers and on the
//! glare grids, light scenes, daylight,
//! the surfaces' illuminance, probes and warnings, in lx, cd/m², lm and %. A part the file
//! does not hold is left out. The page is written through `io::atomic`.

mod base64;
mod daylight;
mod glare;
mod glare_grids;
mod grids;
mod h5;
mod html;
mod light_scenes;
mod luminaires;
mod page;
mod probes;
mod surfaces;

use super::IoError;
use super::read::{File, Why, open};
use std::path::Path;

/// Writes the report of the solution file `solution` to `out` (HTML).
pub fn write_report(solution: &Path, out: &Path) -> Result<(), IoError> {
    let stored = super::read_solution(solution)?;
    let (file, bytes) = open(solution)?;
    let h = h5::H5(File { h5: &file, bytes });
    let shown = solution.file_name().map_or(solution.display().to_string(), |n| n.to_string_lossy().into_owned());
    let html = page::page(&h, &stored, &shown)
        .map_err(|Why(why)| IoError::NotASolution { path: solution.to_path_buf(), why })?;
    super::write_bytes(out, html.as_bytes())
}
