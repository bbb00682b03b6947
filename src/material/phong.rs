//! Normalized modified Phong (Lafortune & Willems 1994): `ρ = k_d + k_s (n+2)/2 cosⁿα`.
//! The glossy lobe is integrated by sampling `cosⁿα` around the mirror direction
//! (pdf `(n+1)/(2π) cosⁿα`) on a fixed stratified grid, so exponents up to 10⁵ are resolved.
//! The Monte Carlo estimators sample the same lobe, mixed with cosine sampling of the
//! diffuse part in proportion to `k_d : k_s`.
//!
//! ```toml
//! [[material]]
//! name = "satin"
//! type = "phong"
//! reflectance = 0.3     # required: the diffuse part k_d
//! specular = 0.5        # required: k_s, with k_d + k_s ≤ 1
//! exponent = 40         # required: n, in [0, 100000]
//! ```

use super::cells::{Accumulator, mirror, stratified};
use crate::directions::DirectionSet;
use crate::geometry::Frame;
use crate::geometry::{cone, cosine_direction};
use glam::DVec3;
use std::f64::consts::{FRAC_1_PI, PI, TAU};

/// The `type` that selects this model and the keys it takes.
pub const TYPE: &str = "phong";
/// The keys of `[[material]]` it takes besides `name` and `type`.
pub const KEYS: &[&str] = &["reflectance", "specular", "exponent"];

const STRATA_IN: usize = 12;
const STRATA_LOBE: usize = 48;

/// The luminance factor `ρ(l, l')` of local directions on the same side of the surface.
pub fn luminance_factor(diffuse: f64, specular: f64, exponent: f64, l: DVec3, l_in: DVec3) -> f64 {
    let cos_a = l.dot(mirror(l_in));
    diffuse + if cos_a > 0.0 { specular * (exponent + 2.0) / 2.0 * cos_a.powf(exponent) } else { 0.0 }
}

/// `cos α` of the lobe sample at `u ∈ [0, 1)`: the inverse of the lobe's distribution.
#[inline]
pub fn lobe_cos(exponent: f64, u: f64) -> f64 {
    u.powf(1.0 / (exponent + 1.0))
}

/// Density per solid angle of lobe directions at angle `α` from the mirror direction.
pub fn lobe_pdf(exponent: f64, cos_a: f64) -> f64 {
    if cos_a > 0.0 { (exponent + 1.0) / TAU * cos_a.powf(exponent) } else { 0.0 }
}

/// Density per solid angle of [`sample`]'s directions (`l'.z > 0`).
pub fn pdf(diffuse: f64, specular: f64, exponent: f64, l: DVec3, l_in: DVec3) -> f64 {
    let p = diffuse / (diffuse + specular);
    p * l_in.z.abs() * FRAC_1_PI + (1.0 - p) * lobe_pdf(exponent, l_in.dot(mirror(l)))
}

/// A cosine direction or a lobe direction, chosen by `u[0]` in proportion to `k_d : k_s`;
/// `None` for a black material.
pub fn sample(diffuse: f64, specular: f64, exponent: f64, l: DVec3, u: [f64; 3]) -> Option<DVec3> {
    if diffuse + specular <= 0.0 {
        return None;
    }
    if u[0] * (diffuse + specular) < diffuse {
        return Some(cosine_direction(u[1], u[2]));
    }
    Some(Frame::around(mirror(l)).world(cone(lobe_cos(exponent, u[1]), TAU * u[2])))
}

/// The row-major `K × K` block `ρ̄(k, d)` of the normalised Phong model with the diffuse
/// part `diffuse`, the specular weight `specular` and the exponent `exponent` on `directions`.
pub fn block(diffuse: f64, specular: f64, exponent: f64, directions: &DirectionSet) -> Vec<f64> {
    let k = directions.len();
    let mut acc = Accumulator::new(k);
    for d in 0..k {
        for (l_in, w_in) in stratified(directions, d, STRATA_IN) {
            let r = mirror(l_in);
            let (t, b) = r.any_orthonormal_pair();
            for i in 0..STRATA_LOBE {
                let u = (i as f64 + 0.5) / STRATA_LOBE as f64;
                let cos_a = lobe_cos(exponent, u);
                let sin_a = (1.0 - cos_a * cos_a).max(0.0).sqrt();
                for j in 0..STRATA_LOBE {
                    let phi = TAU * (j as f64 + 0.5) / STRATA_LOBE as f64;
                    let l: DVec3 = (t * phi.cos() + b * phi.sin()) * sin_a + r * cos_a;
                    if l.z <= 0.0 {
                        continue;
                    }
                    // ρ cosθ / pdf = k_s (n+2)/2 · 2π/(n+1) · cosθ
                    let value = specular * PI * (exponent + 2.0) / (exponent + 1.0) * l.z;
                    acc.add(directions.lookup(l), d, value * w_in / (STRATA_LOBE * STRATA_LOBE) as f64);
                }
            }
        }
    }
    let mut block = acc.finish(directions);
    block.iter_mut().for_each(|v| *v += diffuse);
    block
}
