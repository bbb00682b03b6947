//! Perspective projection of a [`Camera`]: one primary ray per (pixel, sample).
//!
//! Central projection through `position`; the image plane at unit distance spans
//! `2·tan(fov/2)` vertically and `aspect` times that horizontally. Samples are
//! stratified in both axes (N-rooks: sample `s` sits in column stratum `s` and in a
//! shuffled row stratum), jittered by a hash of the pixel so images are reproducible.

use crate::random::Rng;
use crate::scene::Camera;
use glam::DVec3;

/// The camera's eye, basis and image size.
#[derive(Debug, Clone, Copy)]
pub struct Projection {
    pub eye: DVec3,
    forward: DVec3,
    /// Image-plane vectors spanning half the image width and half its height.
    right: DVec3,
    up: DVec3,
    pub width: usize,
    pub height: usize,
    pub samples: usize,
}

impl Projection {
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

    /// Direction of sample `s` (of [`Projection::samples`]) of pixel `(px, py)`.
    pub fn sample(&self, px: usize, py: usize, s: usize) -> DVec3 {
        let n = self.samples as u64;
        let pixel = (py * self.width + px) as u64;
        let shift = Rng::keyed(pixel).next_u64() % n;
        let mut jitter = Rng::keyed(pixel ^ ((s as u64 + 1) << 40));
        let (jx, jy) = (jitter.uniform(), jitter.uniform());
        // Row strata are a shuffled permutation: a stride coprime to n, then a shift.
        let stride = if n.is_multiple_of(7) { 1 } else { 7 };
        let row = (s as u64 * stride + shift) % n;
        let x = px as f64 + (s as f64 + jx) / n as f64;
        let y = py as f64 + (row as f64 + jy) / n as f64;
        self.direction(x, y)
    }
}
