//! Camera images of a solved luminance field (`ugo render`).
//!
//! A pixel holds the luminance (cd/m²) a pinhole camera sees through it: the stored
//! luminance of the first patch along each primary ray, in the direction cell pointing
//! back at the eye, averaged over the pixel's samples. Nothing is re-solved or gathered.

mod camera;
mod image;
mod lit;

pub use camera::Projection;
pub use image::{Image, render};
pub use lit::LitScene;
