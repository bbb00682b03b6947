//! `ugo`: a numerical laboratory for the global illumination equation of a 3D scene.
//!
//! The modules follow the data flow of `design.md` §6: [`scene`] (case files) →
//! [`geometry`] (patches) and [`visibility`] (BVH) → [`directions`], [`brdf`] and
//! [`kernel`] (`K = B·G`) → [`model`] (the linear system) → [`solve`] → [`field`],
//! [`energy`], [`probe`], [`grid`] → [`io`] (HDF5).

pub mod basis;
pub mod brdf;
pub mod directions;
pub mod energy;
pub mod field;
pub mod geometry;
pub mod grid;
pub mod io;
pub mod kernel;
pub mod luminaire;
pub mod model;
pub mod photometry;
pub mod probe;
pub mod render;
pub mod scene;
pub mod solve;
pub mod trace;
pub mod visibility;
