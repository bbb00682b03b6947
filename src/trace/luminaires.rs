//! The `[[luminaire]]`s as the Monte Carlo estimators see them (`crate::luminaire`).
//!
//! A luminaire is a delta light: no scattered ray can meet it, so every surface point a
//! path visits gathers each luminaire exactly, `ρ(l, l') E⊥ |cosθ'| / π` with one shadow
//! ray (`luminaire::incoming`). As in the linear system, where their light enters the
//! source term `L0 = L_e + B·D` already reflected once, it is gathered at every vertex up
//! to `max_order`. An ideal mirror cannot reflect a point light to a path (two deltas): the
//! backward estimate misses luminaires seen in mirrors, which the direction cells of the
//! linear system do carry.
//!
//! The eye alone sees a luminaire's luminous opening (`luminaire::luminous_along`), as in
//! the render of the solved field.
//!
//! For light tracing a luminaire is a photon source chosen by flux: a point luminaire
//! sends a photon in a uniform direction with weight `4π I(ω)/Φ` (the weights average 1);
//! parallel light enters through a disc across the beam covering the scene's bounding
//! sphere, carrying `E_n π R²` (through the openings instead when the scene has some:
//! `daylight_photons.rs`).

use super::emitters::Departure;
use crate::geometry::{Frame, Mesh};
use crate::luminaire::{Light, Source, incoming, luminous_along};
use crate::material::MaterialModel;
use crate::scene::Scene;
use crate::visibility::{NO_FACE, Visibility};
use glam::DVec3;
use std::f64::consts::{FRAC_1_PI, PI, TAU};

/// The luminaires of a scene, placed, with their photon fluxes.
#[derive(Debug, Clone)]
pub struct Luminaires {
    sources: Vec<Source>,
    /// Flux of photons each source emits, lm (parallel light: through the disc).
    flux: Vec<f64>,
    /// The bounding sphere of the scene, where parallel light enters.
    centre: DVec3,
    radius: f64,
}

impl Luminaires {
    /// The luminance of the luminous opening the eye at `origin` meets first along the
    /// unit `direction`, if it lies nearer than every surface, cd/m².
    pub fn seen(&self, visibility: &Visibility, origin: DVec3, direction: DVec3) -> Option<f64> {
        let before = visibility.closest_hit(origin, direction, NO_FACE).map_or(f64::INFINITY, |h| h.distance);
        luminous_along(&self.sources, origin, direction, before)
    }

    /// The luminaires of `scene` placed, with the bounding sphere of `mesh` where parallel
    /// light enters.
    pub fn of(scene: &Scene, mesh: &Mesh) -> Luminaires {
        let sources: Vec<Source> = scene.luminaires.iter().map(Source::of).collect();
        let (lo, hi) = mesh
            .patches
            .iter()
            .flat_map(|p| p.polygon.vertices().iter())
            .fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(lo, hi), &v| (lo.min(v), hi.max(v)));
        let (centre, radius) = (0.5 * (lo + hi), (0.5 * (hi - lo).length()).max(1e-9) * 1.001);
        let flux = sources
            .iter()
            .map(|s| match &s.light {
                Light::Point { .. } => s.flux().unwrap_or(0.0),
                Light::Parallel { illuminance, .. } => illuminance * PI * radius * radius,
                Light::Window { .. } => 0.0,
            })
            .collect();
        Luminaires { sources, flux, centre, radius }
    }

    /// The same luminaires with no photons from parallel light, whose beams enter through
    /// the openings instead (`daylight_photons.rs`).
    pub fn without_beams(mut self) -> Luminaires {
        for (source, flux) in self.sources.iter().zip(self.flux.iter_mut()) {
            if matches!(source.light, Light::Parallel { .. }) {
                *flux = 0.0;
            }
        }
        self
    }

    /// Total photon flux, lm.
    pub fn flux(&self) -> f64 {
        self.flux.iter().sum()
    }

    /// The luminaires' light at `point` of face `face` (local frame `frame`, material
    /// `material`) leaving towards the local direction `out`, cd/m².
    pub fn reflected(
        &self,
        visibility: &Visibility,
        material: &MaterialModel,
        frame: &Frame,
        point: DVec3,
        face: u32,
        out: DVec3,
    ) -> f64 {
        let mut l = 0.0;
        for source in &self.sources {
            if let Some((towards, normal)) = incoming(source, visibility, point, face) {
                let l_in = frame.local(towards);
                l += material.luminance_factor(out, l_in) * normal * l_in.z.abs() * FRAC_1_PI;
            }
        }
        l
    }

    /// Illuminance, lx, on a receiver at `p` facing the unit `n`, lying on face `ignore`.
    pub fn illuminance(&self, visibility: &Visibility, p: DVec3, n: DVec3, ignore: u32) -> f64 {
        let mut e = 0.0;
        for source in &self.sources {
            if let Some((towards, normal)) = incoming(source, visibility, p, ignore) {
                e += normal * towards.dot(n).max(0.0);
            }
        }
        e
    }

    /// A photon: `u[0]` picks a source by flux, the rest place it; with its weight.
    pub fn emit(&self, u: [f64; 5]) -> Option<(Departure, f64)> {
        let total = self.flux();
        if total <= 0.0 {
            return None;
        }
        let mut pick = u[0] * total;
        let i = self.flux.iter().position(|&f| {
            let here = pick < f;
            pick -= f;
            here
        });
        let last = self.flux.iter().rposition(|&f| f > 0.0)?;
        let source = &self.sources[i.unwrap_or(last)];
        match &source.light {
            Light::Point { position, .. } => {
                let z = 1.0 - 2.0 * u[1];
                let r = (1.0 - z * z).max(0.0).sqrt();
                let direction = DVec3::new(r * (TAU * u[2]).cos(), r * (TAU * u[2]).sin(), z);
                let weight = 4.0 * PI * source.intensity(direction) / source.flux()?;
                Some((Departure { origin: *position, direction, face: NO_FACE }, weight))
            }
            Light::Parallel { direction, .. } => {
                let across = Frame::around(*direction);
                let (r, phi) = (self.radius * u[3].sqrt(), TAU * u[4]);
                let origin = self.centre - *direction * 2.0 * self.radius
                    + (across.tangent * phi.cos() + across.bitangent * phi.sin()) * r;
                Some((Departure { origin, direction: *direction, face: NO_FACE }, 1.0))
            }
            Light::Window { .. } => None,
        }
    }
}
