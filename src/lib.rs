//! `ugo`: a numerical laboratory for the global illumination equation of a 3D scene.
//!
//! The modules stand on floors (`docs/design.md` §6): each imports only from its own floor or
//! the floors below it, and no two files import each other (`tests/layering/` reads
//! `src/` and enforces both). From the bottom up:
//!
//! 1. vocabulary: [`directions`], [`geometry`], [`visibility`], [`random`], [`progress`], [`interrupt`]
//! 2. physics: [`material`], [`photometry`], [`transfer`], [`sky`], [`luminaire`]
//! 3. kernel: [`kernel`]
//! 4. solve: [`solve`], [`basis`]
//! 5. scene: [`scene`]
//! 6. model: [`model`]
//! 7. readouts: [`readout`]
//! 8. Monte Carlo references: [`trace`]
//! 9. images: [`render`]
//! 10. io, probe placement: [`io`], [`placement`]
//! 11. study: [`study`]
//!
//! The command line (`src/main.rs`, `src/cli/`) stands on top and only calls the library.

#![warn(missing_docs)]

pub mod basis;
pub mod directions;
pub mod geometry;
pub mod interrupt;
pub mod io;
pub mod kernel;
pub mod luminaire;
pub mod material;
pub mod model;
pub mod photometry;
pub mod placement;
pub mod progress;
pub mod random;
pub mod readout;
pub mod render;
pub mod scene;
pub mod sky;
pub mod solve;
pub mod study;
pub mod trace;
pub mod transfer;
pub mod visibility;
