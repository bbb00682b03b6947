//! `ugo render`: pixels of known scenes, the EXR file read back, the command end to end.

mod cli;
mod glossy;
mod junctions;
mod pictures;
mod pixels;
