//! The one integration-test crate of ugo; its folders mirror `src/`.

mod basis;
mod brdf;
mod cie171;
mod cli;
mod directions;
mod grid;
mod hierarchy;
mod kernel;
mod luminaire;
mod photometry;
mod render;
mod scene;
pub mod solve;
mod support;
mod trace;
mod visibility;
