//! GGX microfacet reflection (Walter et al. 2007) with height-correlated Smith masking
//! (Heitz 2014) and no Fresnel factor, plus a diffuse part:
//! `ρ = k_d + k_s π D(h) G₂(l,l') / (4 cosθ cosθ')`. The specular part is integrated by
//! sampling visible-normal-free `D(h) cosθ_h` on a fixed stratified grid and reflecting.
//! The Monte Carlo estimators sample the same half vectors, mixed with cosine sampling of
//! the diffuse part in proportion to `k_d : k_s`.
//!
//! ```toml
//! [[material]]
//! name = "brushed"
//! type = "ggx"
//! reflectance = 0.1     # required: the diffuse part k_d
//! specular = 0.6        # required: k_s, with k_d + k_s ≤ 1
//! roughness = 0.2       # required: α, in [0.001, 1]
//! ```

use super::cells::{Accumulator, stratified};
use crate::directions::DirectionSet;
use crate::geometry::cosine_direction;
use glam::DVec3;
use std::f64::consts::{FRAC_1_PI, PI, TAU};

/// The `type` that selects this model and the keys it takes.
pub const TYPE: &str = "ggx";
/// The keys of `[[material]]` it takes besides `name` and `type`.
pub const KEYS: &[&str] = &["reflectance", "specular", "roughness"];

const STRATA_IN: usize = 12;
const STRATA_LOBE: usize = 48;

/// The half vector sampled from `D(h) cosθ_h` at `u ∈ [0, 1)` and azimuth `phi`; `a2 = α²`.
#[inline]
pub fn half_vector(a2: f64, u: f64, phi: f64) -> DVec3 {
    let cos_h = ((1.0 - u) / (1.0 + (a2 - 1.0) * u)).sqrt();
    let sin_h = (1.0 - cos_h * cos_h).max(0.0).sqrt();
    DVec3::new(sin_h * phi.cos(), sin_h * phi.sin(), cos_h)
}

/// The Trowbridge–Reitz distribution `D(h)` at `cosθ_h`.
pub fn distribution(a2: f64, cos_h: f64) -> f64 {
    let t = (a2 - 1.0) * cos_h * cos_h + 1.0;
    a2 / (PI * t * t)
}

/// Height-correlated Smith masking-shadowing `G₂ = 1/(1 + Λ(θ) + Λ(θ'))`.
#[inline]
pub fn masking(a2: f64, cos_out: f64, cos_in: f64) -> f64 {
    let lambda = |c: f64| (-1.0 + (1.0 + a2 * (1.0 - c * c) / (c * c)).sqrt()) / 2.0;
    1.0 / (1.0 + lambda(cos_out) + lambda(cos_in))
}

/// The luminance factor `ρ(l, l')` of local directions above the surface.
pub fn luminance_factor(diffuse: f64, specular: f64, alpha: f64, l: DVec3, l_in: DVec3) -> f64 {
    let h = (l + l_in).normalize();
    let a2 = alpha * alpha;
    diffuse + specular * PI * distribution(a2, h.z) * masking(a2, l.z, l_in.z) / (4.0 * l.z * l_in.z)
}

/// Density per solid angle of [`sample`]'s directions (`l'.z > 0`).
pub fn pdf(diffuse: f64, specular: f64, alpha: f64, l: DVec3, l_in: DVec3) -> f64 {
    let p = diffuse / (diffuse + specular);
    p * l_in.z.abs() * FRAC_1_PI + (1.0 - p) * lobe_pdf(alpha * alpha, l, l_in)
}

/// `D(h) cosθ_h / (4 |l'·h|)`: the density of GGX lobe directions.
fn lobe_pdf(a2: f64, l: DVec3, l_in: DVec3) -> f64 {
    let h = (l + l_in).normalize();
    if h.z <= 0.0 || l.dot(h) <= 0.0 {
        return 0.0;
    }
    distribution(a2, h.z) * h.z / (4.0 * l_in.dot(h).abs())
}

/// A cosine direction or the reflection about a sampled half vector, chosen by `u[0]` in
/// proportion to `k_d : k_s`; `None` for a black material.
pub fn sample(diffuse: f64, specular: f64, alpha: f64, l: DVec3, u: [f64; 3]) -> Option<DVec3> {
    if diffuse + specular <= 0.0 {
        return None;
    }
    if u[0] * (diffuse + specular) < diffuse {
        return Some(cosine_direction(u[1], u[2]));
    }
    let h = half_vector(alpha * alpha, u[1], TAU * u[2]);
    Some(2.0 * l.dot(h) * h - l)
}

/// The row-major `K × K` block `ρ̄(k, d)` of GGX with the diffuse part `diffuse`, the
/// specular weight `specular` and the roughness `alpha` on `directions`.
pub fn block(diffuse: f64, specular: f64, alpha: f64, directions: &DirectionSet) -> Vec<f64> {
    let k = directions.len();
    let mut acc = Accumulator::new(k);
    let a2 = alpha * alpha;
    for d in 0..k {
        for (l_in, w_in) in stratified(directions, d, STRATA_IN) {
            for i in 0..STRATA_LOBE {
                let u = (i as f64 + 0.5) / STRATA_LOBE as f64;
                for j in 0..STRATA_LOBE {
                    let h = half_vector(a2, u, TAU * (j as f64 + 0.5) / STRATA_LOBE as f64);
                    let l = 2.0 * l_in.dot(h) * h - l_in;
                    if l.z <= 0.0 || l_in.dot(h) <= 0.0 {
                        continue;
                    }
                    // pdf(l) = D cos_h / (4 |l·h|); ρ cosθ / pdf = k_s π G₂ |l·h| / (cosθ' cos_h)
                    let g2 = masking(a2, l.z, l_in.z);
                    let value = specular * PI * g2 * l_in.dot(h) / (l_in.z * h.z);
                    acc.add(directions.lookup(l), d, value * w_in / (STRATA_LOBE * STRATA_LOBE) as f64);
                }
            }
        }
    }
    let mut block = acc.finish(directions);
    block.iter_mut().for_each(|v| *v += diffuse);
    block
}
