//! The luminance meter (`[[probe]] kind = "luminance_meter"`): the mean luminance within a
//! cone of full angle `fov_deg` about the viewing direction `v` at `p`,
//!
//! `L̄ = (1/Ω) ∫_cone L(p, ω) dω`,   `Ω = 2π (1 − cos α)`,   `α = fov/2`,
//!
//! where `L(p, ω)` is the luminance seen along `ω` (`luminance::seen`: the outgoing
//! luminance, gathered from the solved field, of the first surface point the ray meets).
//! The cone is cut into [`RINGS`] × [`SECTORS`] cells of equal solid angle (rings equal in
//! `cos θ`, sectors equal in azimuth) and read along the centre of each, so `L̄` is the
//! plain mean of the samples: exact for a uniform scene, and — the sectors coming in
//! opposite pairs — for a scene whose luminance takes one value on each side of a plane
//! through the axis. Point luminaires have no area: a meter does not see them.

use crate::geometry::Frame;
use crate::model::Model;
use crate::readout::field::Field;
use crate::readout::luminance::seen;
use glam::DVec3;
use rayon::prelude::*;
use std::f64::consts::PI;

/// Rings of the cone, equal in `cos θ`.
pub const RINGS: usize = 8;

/// Sectors of each ring, equal in azimuth (even: they come in opposite pairs).
pub const SECTORS: usize = 16;

/// `L̄`, cd/m², seen from `p` within `fov_deg` (full angle, degrees) about the unit `v`.
pub fn mean_luminance(model: &Model, field: &Field, p: DVec3, v: DVec3, fov_deg: f64) -> f64 {
    let frame = Frame::around(v);
    let cos_edge = (fov_deg.to_radians() / 2.0).cos();
    let direction = |cell: usize| {
        let (ring, sector) = (cell / SECTORS, cell % SECTORS);
        let cos = 1.0 - (ring as f64 + 0.5) / RINGS as f64 * (1.0 - cos_edge);
        let sin = (1.0 - cos * cos).max(0.0).sqrt();
        let phi = 2.0 * PI * (sector as f64 + 0.5) / SECTORS as f64;
        frame.world(DVec3::new(sin * phi.cos(), sin * phi.sin(), cos))
    };
    let total: f64 = (0..RINGS * SECTORS).into_par_iter().map(|cell| seen(model, field, p, direction(cell), 1)).sum();
    total / (RINGS * SECTORS) as f64
}
