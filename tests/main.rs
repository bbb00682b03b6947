//! The one integration-test crate of ugo; its folders mirror `src/`.

mod basis;
mod cie171;
mod cli;
mod directions;
mod geometry;
mod grid;
mod hierarchy;
mod io;
mod kernel;
mod layering;
mod luminaire;
mod material;
mod model;
mod photometry;
mod placement;
mod progress;
mod readout;
mod render;
mod robustness;
mod scene;
mod sky;
pub mod solve;
mod study;
mod support;
mod trace;
mod transfer;
mod visibility;
