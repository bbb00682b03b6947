//! The luminance image of one camera: rayon over rows, samples averaged per pixel; a
//! final gather's rays per pixel are spread over the pixel's samples.

use super::{LitScene, Projection, Shading};
use crate::random::Rng;
use crate::scene::Camera;
use rayon::prelude::*;

/// A luminance image, cd/m², row-major from the top-left pixel.
#[derive(Debug, Clone, PartialEq)]
pub struct Image {
    pub width: usize,
    pub height: usize,
    pub luminance: Vec<f64>,
}

impl Image {
    /// Smallest and largest pixel luminance, cd/m².
    pub fn range(&self) -> (f64, f64) {
        self.luminance.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &l| (lo.min(l), hi.max(l)))
    }
}

/// Renders `camera`'s view of `scene`.
pub fn render(scene: &LitScene, camera: &Camera) -> Image {
    let view = Projection::of(camera);
    let (width, height) = (view.width, view.height);
    let rays = match scene.shading() {
        Shading::Gather { rays } => rays.div_ceil(view.samples),
        _ => 0,
    };
    let mut luminance = vec![0.0; width * height];
    luminance.par_chunks_mut(width).enumerate().for_each(|(py, row)| {
        for (px, pixel) in row.iter_mut().enumerate() {
            let mut rng = Rng::keyed(((py * width + px) as u64) << 20 | 0xA5);
            let sum: f64 = (0..view.samples)
                .map(|s| scene.luminance_along(view.eye, view.sample(px, py, s), rays, &mut rng))
                .sum();
            *pixel = sum / view.samples as f64;
        }
    });
    Image { width, height, luminance }
}
