//! Backward estimates of a camera image: `spp` independent paths per pixel, each through
//! a uniformly jittered point of the pixel (the pixel-area average that `ugo render`
//! approximates with stratified rays), the pixel's mean and its standard error from the
//! spread of its own samples. Rayon runs over rows; pixel `p`'s random stream is keyed
//! by `(seed, p)`, so the image does not depend on the thread count. The paths are
//! `crate::trace`'s; this file only lays them over the pixels.

use super::{Image, Projection};
use crate::random::Rng;
use crate::scene::Camera;
use crate::trace::statistics::Tally;
use crate::trace::{Start, TraceOptions, World, luminance_along};
use rayon::prelude::*;
use std::time::Instant;

/// A traced image: per-pixel mean luminance and its standard error, cd/m².
#[derive(Debug, Clone, PartialEq)]
pub struct TracedImage {
    /// Per-pixel mean luminance, cd/m².
    pub mean: Image,
    /// Per-pixel standard error of the mean, cd/m².
    pub standard_error: Image,
    /// Paths (pixel samples) traced.
    pub paths: u64,
    /// Rays cast (scattering and shadow rays).
    pub rays: u64,
    /// Wall time, s.
    pub seconds: f64,
}

/// Traces `spp` paths through every pixel of `camera`; `progress(rows)` after each row. A
/// signal's stop leaves the rows short (`crate::interrupt`: the caller checks).
pub fn trace_camera(
    world: &World,
    camera: &Camera,
    spp: usize,
    options: &TraceOptions,
    progress: &(dyn Fn(u64) + Sync),
) -> TracedImage {
    let start = Instant::now();
    let view = Projection::of(camera);
    let (width, height) = (view.width, view.height);
    let rows: Vec<(Vec<(f64, f64)>, u64)> = (0..height)
        .into_par_iter()
        .map(|py| {
            let mut rays = 0;
            let row = (0..width)
                .take_while(|_| !crate::interrupt::asked())
                .map(|px| {
                    let mut rng = Rng::stream(options.seed, (py * width + px) as u64);
                    let mut tally = Tally::default();
                    for _ in 0..spp {
                        let (x, y) = (px as f64 + rng.uniform(), py as f64 + rng.uniform());
                        let d = view.direction(x, y);
                        tally.add(luminance_along(world, Start::camera(view.eye, d), &mut rng, options, &mut rays));
                    }
                    tally.mean_and_error(spp as u64)
                })
                .collect();
            progress(1);
            (row, rays)
        })
        .collect();
    let rays = rows.iter().map(|(_, r)| r).sum();
    let pixels = rows.iter().flat_map(|(row, _)| row.iter().copied());
    let (mean, error): (Vec<f64>, Vec<f64>) = pixels.unzip();
    TracedImage {
        mean: Image { width, height, luminance: mean },
        standard_error: Image { width, height, luminance: error },
        paths: (width * height * spp) as u64,
        rays,
        seconds: start.elapsed().as_secs_f64(),
    }
}
