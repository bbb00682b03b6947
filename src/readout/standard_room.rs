//! One standard room of the UGR table (`docs/photometry.md`, "The UGR table"): `X × Y`
//! in multiples of `H`, the luminaires in a regular array of spacing `S = ratio · H` in
//! the plane `H` above the eye, the first row and column `S/2` from the walls, the eye at
//! the middle of the wall `x = 0` looking horizontally along `+z` across the room (scene
//! coordinates, `y` up), and the luminaires turned so that it sees them crosswise or
//! endwise. It owns the array and each luminaire's direct flux onto the reference plane
//! (the floor of `cavity.rs`), the walls and the ceiling, integrated over the
//! luminaire's distribution (`docs/design.md` (5.8)).

use super::cavity::Cavity;
use crate::luminaire::{Light, Source, frame};
use crate::photometry::Distribution;
use glam::DVec3;
use std::f64::consts::PI;

/// How the eye sees the luminaires.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Viewing {
    /// The line of sight in the luminaires' C0 plane (their C90 axis, the lamp axis of a
    /// linear EULUMDAT luminaire, across it).
    Crosswise,
    /// The line of sight in their C90 plane.
    Endwise,
}

impl Viewing {
    /// Both, in the table's order.
    pub const BOTH: [Viewing; 2] = [Viewing::Crosswise, Viewing::Endwise];

    /// The luminaires' turn about the vertical (`luminaire::frame`), degrees: crosswise
    /// the C0 axis points back at the eye's wall, endwise the C90 axis does.
    fn rotate_deg(self) -> f64 {
        match self {
            Viewing::Crosswise => 90.0,
            Viewing::Endwise => 0.0,
        }
    }

    /// Its name in the table.
    pub fn name(self) -> &'static str {
        match self {
            Viewing::Crosswise => "crosswise",
            Viewing::Endwise => "endwise",
        }
    }
}

/// A luminaire's direct flux onto the cavity's surfaces, lm.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Shares {
    /// Onto the reference plane, averaged over the array.
    pub floor: f64,
    /// Onto the walls between the planes: the rest of what it sends downwards.
    pub walls: f64,
    /// Onto the ceiling: what it sends upwards.
    pub ceiling: f64,
}

/// Polar steps of the direct shares' quadrature per hemisphere, and azimuth steps.
const POLAR_STEPS: usize = 360;
const AZIMUTH_STEPS: usize = 360;

/// A standard room as placed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StandardRoom {
    /// The cavity, m.
    pub cavity: Cavity,
    /// The luminaires across and along the line of sight.
    pub counts: [usize; 2],
    /// Their spacing, m.
    pub spacing: f64,
    /// How the eye sees them.
    pub viewing: Viewing,
}

impl StandardRoom {
    /// The room `[x, y]` (multiples of `height`, m) at the spacing-to-height `ratio`.
    pub fn new(size: [f64; 2], height: f64, ratio: f64, viewing: Viewing) -> StandardRoom {
        let spacing = ratio * height;
        let cavity = Cavity { width: size[0] * height, depth: size[1] * height, height };
        let count = |length: f64| ((length / spacing).round() as usize).max(1);
        StandardRoom { cavity, counts: [count(cavity.width), count(cavity.depth)], spacing, viewing }
    }

    /// The luminaire `distribution` placed at the origin, aimed down and turned for the viewing.
    pub fn luminaire(&self, distribution: &Distribution) -> Source {
        let frame = frame(DVec3::NEG_Y, self.viewing.rotate_deg());
        let light = Light::Point { position: DVec3::ZERO, frame, distribution: distribution.clone(), scale: 1.0 };
        Source { name: "luminaire".to_string(), light, dimmed: 1.0 }
    }

    /// The photometric centres, m, the eye at the origin.
    pub fn positions(&self) -> impl Iterator<Item = DVec3> + '_ {
        let [nx, ny] = self.counts;
        let half = self.cavity.width / 2.0;
        let at = move |i: usize| (i as f64 + 0.5) * self.spacing;
        (0..ny).flat_map(move |j| (0..nx).map(move |i| DVec3::new(at(i) - half, self.cavity.height, at(j))))
    }

    /// `source`'s (at the origin, from [`Self::luminaire`]) direct shares, its light
    /// landing on the reference plane averaged over the array: midpoint quadrature over
    /// the sphere, each direction's landing point shifted by the luminaires' positions.
    pub fn shares(&self, source: &Source) -> Shares {
        let (dgamma, dc) = (0.5 * PI / POLAR_STEPS as f64, 2.0 * PI / AZIMUTH_STEPS as f64);
        let (mut floor, mut down, mut up) = (0.0, 0.0, 0.0);
        for k in 0..2 * POLAR_STEPS {
            let gamma = (k as f64 + 0.5) * dgamma;
            let (sin, cos) = gamma.sin_cos();
            for m in 0..AZIMUTH_STEPS {
                let (sc, cc) = ((m as f64 + 0.5) * dc).sin_cos();
                let w = DVec3::new(sin * cc, -cos, sin * sc);
                let flux = source.intensity(w) * sin * dgamma * dc;
                if k >= POLAR_STEPS {
                    up += flux;
                    continue;
                }
                down += flux;
                let reach = self.cavity.height / cos;
                floor += flux * self.landing(w.x * reach, 0) * self.landing(w.z * reach, 1);
            }
        }
        Shares { floor, walls: down - floor, ceiling: up }
    }

    /// The share of the array's rows along `axis` (0 across, 1 along) whose light shifted
    /// by `offset` (m) still lands inside the room: `⌊n + 1/2 − |offset|/S⌋` of `n`.
    fn landing(&self, offset: f64, axis: usize) -> f64 {
        let n = self.counts[axis] as f64;
        (n + 0.5 - offset.abs() / self.spacing).floor().clamp(0.0, n) / n
    }
}
