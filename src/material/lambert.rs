//! Lambert: the ideal diffuse reflector and, on a two-sided surface, diffuse transmitter
//! (`docs/design.md` §1): `ρ ≡ reflectance` on the incident side, `τ ≡ transmittance` through
//! the surface, `reflectance + transmittance ≤ 1`. Every cell average is the constant.
//! Sampled by cosine directions, on the side chosen in proportion to `ρ : τ`.
//!
//! ```toml
//! [[material]]
//! name = "opal"
//! type = "lambert"
//! reflectance = 0.5     # required, in [0, 1]
//! transmittance = 0.3   # optional (default 0); needs `two_sided = true` on its surfaces
//! ```

use crate::geometry::cosine_direction;
use glam::DVec3;
use std::f64::consts::FRAC_1_PI;

/// The `type` that selects this model and the keys it takes.
pub const TYPE: &str = "lambert";
/// The keys of `[[material]]` it takes besides `name` and `type`.
pub const KEYS: &[&str] = &["reflectance", "transmittance"];

/// `ρ` for `l'` on the incident side (`l'.z > 0`), `τ` through the surface.
pub fn luminance_factor(reflectance: f64, transmittance: f64, l_in: DVec3) -> f64 {
    if l_in.z > 0.0 { reflectance } else { transmittance }
}

/// The `K × K` block of a constant luminance factor.
pub fn block(value: f64, k: usize) -> Vec<f64> {
    vec![value; k * k]
}

/// Density per solid angle of [`sample`]'s directions.
pub fn pdf(reflectance: f64, transmittance: f64, l_in: DVec3) -> f64 {
    let total = reflectance + transmittance;
    if total <= 0.0 {
        return 0.0;
    }
    l_in.z.abs() * FRAC_1_PI * luminance_factor(reflectance, transmittance, l_in) / total
}

/// A cosine direction on the side chosen by `u[0]`; `None` for a black material.
pub fn sample(reflectance: f64, transmittance: f64, u: [f64; 3]) -> Option<DVec3> {
    let total = reflectance + transmittance;
    if total <= 0.0 {
        return None;
    }
    let d = cosine_direction(u[1], u[2]);
    Some(if u[0] * total < reflectance { d } else { DVec3::new(d.x, d.y, -d.z) })
}
