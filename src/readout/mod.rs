//! Readouts of a solved field (`design.md` §5, §7): the field as an `N × K × C` array, the
//! illuminance of patches and points, probes, grids and the energy balance in lumens.

pub mod daylight;
pub mod energy;
pub mod field;
pub mod grid;
pub mod illuminance;
pub mod probe;
