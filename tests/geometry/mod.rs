//! Meshing: the tessellation of shapes into patches.

mod concave;
