//! The transfer toolkit of `docs/design.md` §3: how much light a point or a patch receives from
//! a polygon. Exact point-to-polygon form factors (Lambert's contour integral), pair and
//! point factors split by direction cells, visibility fractions from rays between
//! stratified points, and plane mirrors' images. The kernel's assembly, the luminaires' direct light, probes and
//! the final gather all build on it; it knows nothing of materials, kernels or scenes.

pub mod closure;
pub mod contour;
pub mod exposure;
pub mod far_field;
pub mod form_factor;
pub mod image;
pub mod occlusion;
