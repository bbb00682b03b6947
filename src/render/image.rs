//! The luminance image of one camera: rayon over rows, samples averaged per pixel.
//!
//! A final gather shades fewer points than the pixel has samples: the samples measure
//! how much of the pixel each surface covers (`n_c` of `S` samples on surface `c`, a sharp
//! edge measured as finely as flat shading does), and [`GATHER_POINTS`] points of a
//! second stratified set in the pixel give each surface's mean luminance there, `L̄_c`;
//! the pixel is `Σ_c (n_c/S) L̄_c`. A surface that covers samples but none of the points
//! is shaded at its first sample. The gather's rays per pixel are spread over the points.
//! With no more samples than points both sets are the same and every sample is shaded.
//! A sample that meets a light source's own luminance (a luminaire, the sky through an
//! opening: [`Sight::Light`]) adds it as flat shading does; it is not gathered.

use super::{LitScene, Projection, Shading, Sight};
use crate::random::Rng;
use crate::scene::Camera;
use glam::DVec3;
use rayon::prelude::*;

/// Points a final gather shades per pixel (at most; fewer when the camera takes fewer
/// samples). The Cornell study image at 64 samples and 2,048 rays per pixel: 0.97 % from
/// the converged reference in 6.0 s with all 64 shaded, 0.92 % in 2.9 s with 16.
pub const GATHER_POINTS: usize = 16;

/// A luminance image, cd/m², row-major from the top-left pixel.
#[derive(Debug, Clone, PartialEq)]
pub struct Image {
    /// Width, pixels.
    pub width: usize,
    /// Height, pixels.
    pub height: usize,
    /// One value per pixel, cd/m².
    pub luminance: Vec<f64>,
}

impl Image {
    /// Smallest and largest pixel luminance, cd/m².
    pub fn range(&self) -> (f64, f64) {
        self.luminance.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &l| (lo.min(l), hi.max(l)))
    }
}

/// Renders `camera`'s view of `scene`. A stop asked for by a signal leaves the pixels not
/// yet shaded black (`crate::interrupt`: the caller checks before using the image).
pub fn render(scene: &LitScene, camera: &Camera) -> Image {
    let view = Projection::of(camera);
    let (width, height) = (view.width, view.height);
    let mut luminance = vec![0.0; width * height];
    luminance.par_chunks_mut(width).enumerate().for_each(|(py, row)| {
        let mut surfaces = Vec::new();
        for (px, pixel) in row.iter_mut().enumerate().take_while(|_| !crate::interrupt::asked()) {
            let mut rng = Rng::keyed(((py * width + px) as u64) << 20 | 0xA5);
            *pixel = match scene.shading() {
                Shading::Gather { rays } => gathered(scene, &view, [px, py], rays, &mut rng, &mut surfaces),
                _ => {
                    (0..view.samples)
                        .map(|s| scene.luminance_along(view.eye, view.sample(px, py, s), 0, &mut rng))
                        .sum::<f64>()
                        / view.samples as f64
                }
            };
        }
    });
    Image { width, height, luminance }
}

/// One surface side seen in a pixel: samples covered, the first of them, and the sum and
/// count of its shaded points.
struct Seen {
    key: u64,
    covered: usize,
    first: usize,
    sum: f64,
    shaded: usize,
}

/// The pixel's luminance with a final gather of `rays` per pixel (module documentation).
fn gathered(
    scene: &LitScene,
    view: &Projection,
    [px, py]: [usize; 2],
    rays: usize,
    rng: &mut Rng,
    seen: &mut Vec<Seen>,
) -> f64 {
    let points = view.samples.min(GATHER_POINTS);
    let rays = rays.div_ceil(points);
    seen.clear();
    let mut lights = 0.0;
    for s in 0..view.samples {
        match scene.sight(view.eye, view.sample(px, py, s)) {
            Some(Sight::Patch(patch, _)) => {
                let key = scene.side_of(patch);
                match seen.iter_mut().find(|c| c.key == key) {
                    Some(c) => c.covered += 1,
                    None => seen.push(Seen { key, covered: 1, first: s, sum: 0.0, shaded: 0 }),
                }
            }
            Some(Sight::Light(luminance)) => lights += luminance,
            None => {}
        }
    }
    for s in 0..points {
        shade(scene, view.eye, view.point(px, py, s, points), rays, rng, seen);
    }
    for i in 0..seen.len() {
        if seen[i].shaded == 0 {
            shade(scene, view.eye, view.sample(px, py, seen[i].first), rays, rng, seen);
        }
    }
    let surfaces: f64 = seen.iter().map(|c| c.covered as f64 * c.sum / c.shaded.max(1) as f64).sum();
    (surfaces + lights) / view.samples as f64
}

/// Shades the point seen along `direction` into the surface side it lies on, if that side
/// covers samples of the pixel (`seen`).
fn shade(scene: &LitScene, eye: DVec3, direction: DVec3, rays: usize, rng: &mut Rng, seen: &mut [Seen]) {
    let Some(Sight::Patch(patch, q)) = scene.sight(eye, direction) else { return };
    let key = scene.side_of(patch);
    if let Some(c) = seen.iter_mut().find(|c| c.key == key) {
        c.sum += scene.shade(patch, q, -direction, rays, rng);
        c.shaded += 1;
    }
}
