//! Meshing: the tessellation of shapes into patches.

mod clip;
mod concave;
mod holes;
mod split;
