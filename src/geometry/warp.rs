//! Warps from uniform numbers to directions about `+z`, shared by the samplers of the
//! materials, the Monte Carlo estimators and the closure's rays (`transfer::closure`).

use glam::DVec3;
use std::f64::consts::TAU;

/// Cosine-distributed direction about `+z` (Malley's method): density `cosθ/π`.
pub fn cosine_direction(u1: f64, u2: f64) -> DVec3 {
    let r = u1.sqrt();
    let phi = TAU * u2;
    DVec3::new(r * phi.cos(), r * phi.sin(), (1.0 - u1).max(0.0).sqrt())
}

/// The direction at polar cosine `cos` and azimuth `phi` about `+z`.
pub fn cone(cos: f64, phi: f64) -> DVec3 {
    let sin = (1.0 - cos * cos).max(0.0).sqrt();
    DVec3::new(sin * phi.cos(), sin * phi.sin(), cos)
}
