//! Readouts of a solved field (`docs/design.md` §5, §7): the field as an `N × K × C` array, the
//! illuminance of patches and points, probes (point sensors, luminance meters, cylindrical
//! illuminance), the UGR at observers and on glare grids, a grid's UGR from them and the UGR
//! table of a luminaire, grids, the readings' error bars and the energy balance in lumens.

pub mod cavity;
pub mod correction;
pub mod cut;
pub mod cylindrical;
pub mod daylight;
pub mod energy;
pub mod error_bar;
pub mod field;
pub mod final_gather;
pub mod gather;
pub mod glare_grid;
pub mod glossy;
pub mod grid;
pub mod grid_error;
pub mod grid_ugr;
pub mod group_readouts;
pub mod guth;
pub mod illuminance;
pub mod lit;
pub mod luminance;
pub mod meter;
pub mod mirrored;
pub mod obstructed;
pub mod openings;
pub mod probe;
pub mod readings;
pub mod residual_samples;
mod runs;
pub mod standard_room;
pub mod ugr;
pub mod ugr_table;
