//! The light sources of the estimators: the source term `L0` of `docs/design.md` §1 as things
//! to sample. Every emitting patch is an area emitter of Lambertian luminance `L0`
//! (cd/m², from `mesh.emission`, which already turned a surface's flux into luminance)
//! and flux `Φ = π L0 A` (lm).
//!
//! Emitting patches are chosen in proportion to their flux, both for next-event
//! estimation (a point seen from a surface point, with its density per solid angle there)
//! and for photon emission (a point and a Lambertian direction). Luminaires are sampled
//! apart, exactly (`luminaires.rs`).

use crate::geometry::Mesh;
use crate::geometry::cosine_direction;
use glam::DVec3;
use std::f64::consts::PI;

/// Light arriving at a surface point from a sampled point of an emitter.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Incoming {
    /// Unit direction from the receiving point towards the emitter.
    pub direction: DVec3,
    /// The sampled point on the emitter.
    pub point: DVec3,
    /// The emitter's face (ignored by the shadow ray).
    pub face: u32,
    /// Luminance arriving along `direction`, cd/m².
    pub luminance: f64,
    /// Density of this sample per solid angle at the receiving point.
    pub pdf: f64,
}

/// A photon leaving an emitter.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Departure {
    /// The point it leaves from, m.
    pub origin: DVec3,
    /// Its unit direction.
    pub direction: DVec3,
    /// The face it leaves from (ignored by its first ray).
    pub face: u32,
}

/// Every emitter of a scene with its share of the total flux.
#[derive(Debug, Clone)]
pub struct Emitters {
    /// The emitting patches (each emits its Lambertian luminance from its front side).
    list: Vec<u32>,
    /// Cumulative flux fractions, last = 1.
    cdf: Vec<f64>,
    /// Probability of choosing each patch (0 for non-emitting ones).
    chance: Vec<f64>,
    total: f64,
}

impl Emitters {
    /// The emitting patches of `mesh`.
    pub fn of(mesh: &Mesh) -> Emitters {
        let flux: Vec<f64> = mesh.patches.iter().zip(&mesh.emission).map(|(p, &l)| PI * l * p.area).collect();
        let total: f64 = flux.iter().sum();
        let mut list = Vec::new();
        let mut cdf = Vec::new();
        let mut running = 0.0;
        for (i, &f) in flux.iter().enumerate() {
            if f > 0.0 {
                running += f;
                list.push(i as u32);
                cdf.push(running / total);
            }
        }
        if let Some(last) = cdf.last_mut() {
            *last = 1.0;
        }
        let chance = flux.iter().map(|f| if total > 0.0 { f / total } else { 0.0 }).collect();
        Emitters { list, cdf, chance, total }
    }

    /// Total luminous flux of the sources, lm.
    pub fn flux(&self) -> f64 {
        self.total
    }

    /// True when no patch emits.
    pub fn is_empty(&self) -> bool {
        self.list.is_empty()
    }

    /// The emitter whose flux interval holds `u`, and `u` rescaled to `[0, 1)` within it.
    fn pick(&self, u: f64) -> (u32, f64) {
        let i = self.cdf.partition_point(|&c| c <= u).min(self.list.len() - 1);
        let start = if i == 0 { 0.0 } else { self.cdf[i - 1] };
        let width = self.cdf[i] - start;
        let v = if width > 0.0 { ((u - start) / width).clamp(0.0, 1.0 - f64::EPSILON) } else { 0.0 };
        (self.list[i], v)
    }

    /// A point of an emitter seen from `x` (next-event estimation); `None` when the sampled
    /// point turns its back on `x` or there is no emitter.
    pub fn sample_towards(&self, mesh: &Mesh, x: DVec3, u: [f64; 3]) -> Option<Incoming> {
        if self.list.is_empty() {
            return None;
        }
        let (patch, v) = self.pick(u[0]);
        let p = &mesh.patches[patch as usize];
        let point = p.polygon.point_at(v, u[1], u[2]);
        let to = point - x;
        let distance2 = to.length_squared();
        let direction = to / distance2.sqrt();
        let cos_y = -p.normal.dot(direction);
        if cos_y <= 0.0 || distance2 <= 0.0 {
            return None;
        }
        let pdf = self.chance[patch as usize] / p.area * distance2 / cos_y;
        Some(Incoming { direction, point, face: p.face, luminance: mesh.emission[patch as usize], pdf })
    }

    /// Density per solid angle at `x` with which [`Emitters::sample_towards`] picks point
    /// `y` of patch `patch` (for multiple importance sampling when a scattered ray meets it).
    pub fn pdf_towards(&self, mesh: &Mesh, patch: usize, x: DVec3, y: DVec3) -> f64 {
        let p = &mesh.patches[patch];
        let to = y - x;
        let distance2 = to.length_squared();
        let cos_y = -p.normal.dot(to) / distance2.sqrt();
        if cos_y <= 0.0 { 0.0 } else { self.chance[patch] / p.area * distance2 / cos_y }
    }

    /// A photon: an emitter chosen by flux, a uniform point on it, a cosine-distributed
    /// direction (a Lambertian emitter's); five uniform numbers.
    pub fn emit(&self, mesh: &Mesh, u: [f64; 5]) -> Option<Departure> {
        if self.list.is_empty() {
            return None;
        }
        let (patch, v) = self.pick(u[0]);
        let p = &mesh.patches[patch as usize];
        let origin = p.polygon.point_at(v, u[1], u[2]);
        let direction = p.frame().world(cosine_direction(u[3], u[4]));
        Some(Departure { origin, direction, face: p.face })
    }
}
