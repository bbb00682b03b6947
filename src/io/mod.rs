//! Output files: the HDF5 dump of a solve (`design.md` §8).

mod hdf5_file;

pub use hdf5_file::{Solution, write_solution};
