//! Files: the HDF5 dump of a solve (`docs/design.md` §8) written and read back,
//! the HDF5 file of a forward Monte Carlo estimate, convergence plots, and rendered images
//! (linear EXR, read back for comparisons; tone-mapped PNG; false colour; the difference
//! from a traced reference), the grids' plans, the spectrum of `K` with its plot, and the
//! HTML report of a solved case.

mod atomic;
mod basis_plot;
mod bytes_file;
mod dataset;
mod daylight_group;
mod difference_map;
mod error;
mod estimate_file;
mod export;
mod exr_file;
mod false_colour;
mod glare_grid_csv;
mod glare_grid_group;
mod grid_map;
mod hdf5_file;
mod hierarchy_group;
mod hierarchy_kernel;
mod isolines;
mod kernel_file;
mod light_scene_group;
mod lock;
mod no_room;
mod observer_group;
mod part_file;
mod part_rows_file;
mod plan;
mod plan_marks;
mod plot;
mod png_file;
mod read;
mod readings;
mod readout_file;
mod readout_group;
mod report;
mod solution;
mod spectrum_file;
mod spectrum_plot;
mod ticks;
mod triptych;
mod ugr_table_csv;
mod warning;
mod warning_lines;

pub use basis_plot::basis_plot;
pub use bytes_file::write_bytes;
pub use difference_map::{DIFFERENCE_SIDE, WITHIN_NOISE, magnification, relative_difference, write_difference};
pub use error::IoError;
pub use estimate_file::{EstimateFile, write_estimate};
pub use export::{ExportError, Format, export};
pub use exr_file::{read_exr, write_exr, write_exr_as};
pub use false_colour::{LEGEND_WIDTH, Scale, colour, position, write_false_colour};
pub use glare_grid_csv::write_glare_grid_csv;
pub use grid_map::{GridPlan, write_daylight_map, write_grid_map};
pub use hdf5_file::write_solution;
pub use isolines::isolines;
pub use kernel_file::{StoredKernel, read_kernel};
pub use light_scene_group::{
    GroupField, LightSceneField, LightScenes, StoredGroup, read_group_readouts, read_light_groups, read_light_scene,
};
pub use lock::OutputLock;
pub use no_room::survive_size_limit;
pub use part_file::{StoredPart, read_part, read_part_for, write_part};
pub use part_rows_file::write_part_rows;
pub use plan::{Axis, Frame, Layout};
pub use plan_marks::Overlay;
pub use plot::{convergence_plot, register_font};
pub use png_file::{auto_exposure, srgb, write_png};
pub use read::{StoredSolution, read_solution};
pub use readings::{write_grid_csv, write_probes_csv};
pub use readout_file::{Readout, write_readout};
pub use report::write_report;
pub use solution::{KernelRecord, Loaded, MonteCarlo, Run, Solution};
pub use spectrum_file::{Mode, read_mode};
pub use spectrum_plot::{RateLine, spectrum_plot};
pub use ticks::{log_ticks, round_125, round_top, step, tick_label, ticks};
pub use triptych::{CAPTION_HEIGHT, write_triptych};
pub use ugr_table_csv::write_ugr_table_csv;
pub use warning::{LeftOut, MirrorCause, NegativeEscape, SensorFault, Warning};
pub use warning_lines::{LINE, NOTE_SHARE, merged, one_line, told};

use atomic::{atomic, atomic_png};
