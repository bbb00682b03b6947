//! Perspective projection of a [`Camera`]: one primary ray per (pixel, sample).
//!
//! Central projection through `position`; the image plane at unit distance spans
//! `2·tan(fov/2)` vertically and `aspect` times that horizontally. A pixel's samples are
//! a Hammersley set shifted by a hash of the pixel (`random::Stratified`): stratified in
//! both axes and in every dyadic grid of the pixel, so an edge's coverage is measured
//! about as well as the sample count allows, and images are reproducible.

use crate::random::{Rng, Stratified};
use crate::scene::Camera;
use glam::DVec3;

/// The camera's eye, basis and image size.
#[derive(Debug, Clone, Copy)]
pub struct Projection {
    /// The centre of projection, m.
    pub eye: DVec3,
    forward: DVec3,
    /// Image-plane vectors spanning half the image width and half its height.
    right: DVec3,
    up: DVec3,
    /// Image width, pixels.
    pub width: usize,
    /// Image height, pixels.
    pub height: usize,
    /// Primary rays per pixel.
    pub samples: usize,
}

impl Projection {
    /// The projection of a `[[camera]]`.
    pub fn of(camera: &Camera) -> Projection {
        let forward = (camera.look_at - camera.position).normalize();
        let right = forward.cross(camera.up).normalize();
        let up = right.cross(forward);
        let [width, height] = camera.resolution;
        let half = (camera.fov_deg.to_radians() / 2.0).tan();
        let aspect = width as f64 / height as f64;
        Projection {
            eye: camera.position,
            forward,
            right: right * half * aspect,
            up: up * half,
            width,
            height,
            samples: camera.samples,
        }
    }

    /// Unit direction through image point `(x, y)` in pixels from the top-left corner.
    pub fn direction(&self, x: f64, y: f64) -> DVec3 {
        let u = 2.0 * x / self.width as f64 - 1.0;
        let v = 1.0 - 2.0 * y / self.height as f64;
        (self.forward + u * self.right + v * self.up).normalize()
    }

    /// Whether any sample ray of pixel `(px, py)` satisfies `test`.
    pub fn any_sample(&self, [px, py]: [usize; 2], test: &dyn Fn(DVec3) -> bool) -> bool {
        (0..self.samples).any(|s| test(self.sample(px, py, s)))
    }

    /// Every pixel, row by row from the top left.
    pub fn pixels(&self) -> impl Iterator<Item = [usize; 2]> + '_ {
        (0..self.height).flat_map(move |py| (0..self.width).map(move |px| [px, py]))
    }

    /// Direction of sample `s` (of [`Projection::samples`]) of pixel `(px, py)`.
    pub fn sample(&self, px: usize, py: usize, s: usize) -> DVec3 {
        self.point(px, py, s, self.samples)
    }

    /// Direction of point `s` of a set of `n` in pixel `(px, py)` (with `n` the sample
    /// count, the samples themselves).
    pub fn point(&self, px: usize, py: usize, s: usize, n: usize) -> DVec3 {
        let pixel = (py * self.width + px) as u64;
        let [x, y] = Stratified::new(n, &mut Rng::keyed(pixel)).point(s);
        self.direction(px as f64 + x, py as f64 + y)
    }
}
