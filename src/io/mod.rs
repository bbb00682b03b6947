//! Files: the HDF5 dump of a solve (`design.md` §8) written and read back,
//! the HDF5 file of a forward Monte Carlo estimate, convergence plots, and rendered images
//! (linear EXR, read back for comparisons; tone-mapped PNG; false colour).

mod basis_plot;
mod error;
mod estimate_file;
mod exr_file;
mod false_colour;
mod hdf5_file;
mod hierarchy_group;
mod plot;
mod png_file;
mod read;
mod readings;
mod triptych;

pub use basis_plot::basis_plot;
pub use error::IoError;
pub use estimate_file::{EstimateFile, write_estimate};
pub use exr_file::{read_exr, write_exr, write_exr_as};
pub use false_colour::{LEGEND_WIDTH, Scale, colour, position, write_false_colour};
pub use hdf5_file::{BasisRecord, Run, Solution, write_solution};
pub use plot::{convergence_plot, register_font};
pub use png_file::{auto_exposure, srgb, write_png};
pub use read::{StoredSolution, read_solution};
pub use readings::{write_grid_csv, write_grid_map, write_probes_csv};
pub use triptych::{CAPTION_HEIGHT, write_triptych};

use std::path::{Path, PathBuf};

/// Runs `write` on `path.tmp` and renames it to `path` when it succeeds; removes the
/// temporary file when it fails. The one temporary-name-and-rename of every output.
fn atomic(path: &Path, write: impl FnOnce(&Path) -> Result<(), String>) -> Result<(), IoError> {
    let mut tmp = path.as_os_str().to_owned();
    tmp.push(".tmp");
    let tmp = PathBuf::from(tmp);
    match write(&tmp) {
        Ok(()) => std::fs::rename(&tmp, path)
            .map_err(|e| IoError::write(path, format!("cannot rename {} to it: {e}", tmp.display()))),
        Err(why) => {
            let _ = std::fs::remove_file(&tmp);
            Err(IoError::write(path, why))
        }
    }
}
