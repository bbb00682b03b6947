//! Meshing: the tessellation of shapes into patches.

mod angle;
mod clip;
mod concave;
mod holes;
mod split;
