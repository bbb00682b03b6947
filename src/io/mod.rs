//! Output files: the HDF5 dump of a solve (`design.md` §8) and convergence plots.

mod hdf5_file;
mod plot;

pub use hdf5_file::{Run, Solution, write_solution};
pub use plot::convergence_plot;
