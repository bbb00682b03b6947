//! Camera images of a solved luminance field (`ugo render`).
//!
//! A pixel holds the luminance (cd/m²) a pinhole camera sees through it: the luminance
//! leaving the first surface along each primary ray towards the eye, averaged over the
//! pixel's samples, shaded flat (the stored patch value), smooth (interpolated between
//! patches of one surface) or by a final gather (one more reflection at the hit point).
//! Where the ray meets a luminaire's luminous opening first, or leaves the scene through a
//! `[[window]]`, the pixel shows the luminaire's luminance, or the sky's and the ground's
//! (`lit.rs`, `crate::luminaire::luminous_along`).
//!
//! The same camera traced by Monte Carlo (`ugo trace`, `traced.rs`): per-pixel means and
//! standard errors of `crate::trace`'s backward paths, the independent check of a render.

mod camera;
mod image;
mod lit;
mod smooth;
mod solved;
mod traced;

pub use camera::Projection;
pub use image::{GATHER_POINTS, Image, render};
pub use lit::{LitScene, Shading, Sight};
pub use solved::Solved;
pub use traced::{TracedImage, trace_camera};
