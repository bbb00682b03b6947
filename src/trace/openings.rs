//! The `[[window]]` openings as the Monte Carlo estimators see them (`crate::sky`,
//! `docs/daylight.md`): a ray that leaves the scene through an opening brings in the
//! sky's luminance `L_sky(l)` above the horizon and the ground's below it
//! (`Sky::luminance`), times the glazing's `τ(θ)` at its incidence on the opening.
//!
//! Like the emitting patches, the openings are sampled for next-event estimation: an
//! opening chosen in proportion to its area, a uniform point on it, a shadow ray from the
//! receiving point through it that must leave the scene (obstructions inside and outside
//! block it, as the deterministic `sees`). Its density per solid angle is
//! `Σ_j P(j) t_j² / (A_j |cos θ_j|)` over every opening `j` the ray crosses at distance
//! `t_j`, so a direction reached both ways (sampled towards an opening, or scattered by
//! the material and escaping) is weighted by the power heuristic. A ray through several
//! openings sees the sky once, times the product of their glazings (the deterministic
//! path adds the openings, the same unless one opening is seen through another).
//!
//! A camera sees the sky through an opening as it does in the render of the solved field
//! (`crate::render`, which reads it here); a probe's luminance is its first surface's.

use super::emitters::Incoming;
use crate::luminaire::{Light, Source};
use crate::sky::{Opening, Sky};
use crate::visibility::{NO_FACE, Visibility};
use glam::DVec3;

/// The openings of a scene and the sky each lets in.
#[derive(Debug, Clone)]
pub struct Openings {
    list: Vec<(Opening, Sky)>,
    /// Probability of choosing each opening: its share of the openings' area.
    chance: Vec<f64>,
}

/// What a ray sees through the openings it crosses.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Seen {
    /// Luminance arriving along the ray, cd/m² (the ray must leave the scene).
    pub luminance: f64,
    /// Density per solid angle with which [`Openings::sample_towards`] picks the ray.
    pub pdf: f64,
}

impl Openings {
    /// The openings among `sources`.
    pub fn of(sources: &[Source]) -> Openings {
        let list: Vec<(Opening, Sky)> = sources
            .iter()
            .filter_map(|s| match &s.light {
                Light::Window { window, sky } => Some((*window, sky.clone())),
                _ => None,
            })
            .collect();
        let total: f64 = list.iter().map(|(o, _)| o.polygon.area()).sum();
        let chance = list.iter().map(|(o, _)| o.polygon.area() / total).collect();
        Openings { list, chance }
    }

    /// True when the scene has no openings.
    pub fn is_empty(&self) -> bool {
        self.list.is_empty()
    }

    /// The luminance along the unit `direction` from `x` and the density of sampling it,
    /// if the ray crosses an opening; whether it then leaves the scene is the caller's.
    pub fn seen(&self, x: DVec3, direction: DVec3) -> Option<Seen> {
        let (mut nearest, mut sky, mut transmittance, mut pdf) = (f64::INFINITY, None, 1.0, 0.0);
        for ((opening, outside), chance) in self.list.iter().zip(&self.chance) {
            let Some(t) = opening.polygon.crossing(x, direction) else { continue };
            let cos = direction.dot(opening.polygon.normal()).abs();
            pdf += chance / opening.polygon.area() * t * t / cos;
            transmittance *= opening.glazing.map_or(1.0, |g| g.transmittance(cos));
            if t < nearest {
                (nearest, sky) = (t, Some(outside));
            }
        }
        sky.map(|s| Seen { luminance: s.luminance(direction) * transmittance, pdf })
    }

    /// A point of an opening seen from `x` (next-event estimation): the direction towards
    /// it, the luminance arriving and the density; `None` without openings or when `x`
    /// lies in the opening's plane. The shadow ray is [`Openings::clear`].
    pub fn sample_towards(&self, x: DVec3, u: [f64; 3]) -> Option<Incoming> {
        let (index, v) = pick(&self.chance, u[0])?;
        let point = self.list[index].0.polygon.point_at(v, u[1], u[2]);
        let direction = (point - x).normalize_or_zero();
        let seen = self.seen(x, direction).filter(|s| s.pdf.is_finite() && s.pdf > 0.0)?;
        Some(Incoming { direction, point, face: NO_FACE, luminance: seen.luminance, pdf: seen.pdf })
    }

    /// True when the ray from `x` (on face `ignore`) along the unit `direction` leaves the
    /// scene: nothing inside or outside stops it.
    pub fn clear(visibility: &Visibility, x: DVec3, direction: DVec3, ignore: u32) -> bool {
        visibility.escapes(x, direction, ignore)
    }
}

/// The index whose share of `[0, 1)` holds `u`, and `u` rescaled to `[0, 1)` within it.
pub(super) fn pick(chance: &[f64], u: f64) -> Option<(usize, f64)> {
    let mut start = 0.0;
    for (i, &c) in chance.iter().enumerate() {
        if u < start + c || i + 1 == chance.len() {
            return Some((i, ((u - start) / c).clamp(0.0, 1.0 - f64::EPSILON)));
        }
        start += c;
    }
    None
}
