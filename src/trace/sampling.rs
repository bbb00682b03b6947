//! The continuous materials of `design.md` §1 for the Monte Carlo estimators: the
//! luminance factor `ρ(l, l')` (and `τ` through a two-sided surface), importance sampling
//! of the integrand `(1/π) ρ(l, l') |cosθ'| dω'` and its density.
//!
//! Directions are in the patch's local frame, `l.z > 0` (the patch faces `l`); an incoming
//! direction with `l'.z < 0` arrives through the surface (Lambert transmission only).
//! The lobe samplers and formulas are those of `crate::material` (Phong: `cosⁿα` around the
//! mirror direction; GGX: `D(h) cosθ_h`), mixed with cosine sampling of the diffuse part
//! in proportion to `k_d : k_s`. By reciprocity `ρ(l, l') = ρ(l', l)` the same sampler
//! serves paths from the eye (backward) and from the source (forward).

use crate::material::{ggx, mirror_image, phong};
use crate::geometry::Frame;
use crate::material::MaterialModel;
use glam::DVec3;
use std::f64::consts::{FRAC_1_PI, TAU};

/// One sampled direction.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sample {
    /// Local unit direction `l'`.
    pub direction: DVec3,
    /// `ρ(l, l') |cosθ'| / (π pdf)`: the factor the path's throughput is multiplied by.
    pub weight: f64,
    /// Density per solid angle (0 for the mirror's delta).
    pub pdf: f64,
    /// True for an ideal mirror: no light source can be sampled towards it.
    pub delta: bool,
}

/// True when the material scatters into a single direction (no next-event estimation).
pub fn is_delta(model: &MaterialModel) -> bool {
    matches!(model, MaterialModel::Mirror { .. })
}

/// The luminance factor `ρ(l, l')` (reflection) or `τ` (through the surface, `l'.z < 0`).
pub fn evaluate(model: &MaterialModel, l: DVec3, l_in: DVec3) -> f64 {
    match *model {
        MaterialModel::Lambert { reflectance, transmittance } => {
            if l_in.z > 0.0 {
                reflectance
            } else {
                transmittance
            }
        }
        _ if l_in.z <= 0.0 => 0.0,
        MaterialModel::Mirror { .. } => 0.0,
        MaterialModel::Phong { diffuse, specular, exponent } => {
            phong::luminance_factor(diffuse, specular, exponent, l, l_in)
        }
        MaterialModel::Ggx { diffuse, specular, roughness } => {
            ggx::luminance_factor(diffuse, specular, roughness, l, l_in)
        }
    }
}

/// Density per solid angle with which [`sample`] picks `l_in` given `l`.
pub fn pdf(model: &MaterialModel, l: DVec3, l_in: DVec3) -> f64 {
    let cosine = l_in.z.abs() * FRAC_1_PI;
    match *model {
        MaterialModel::Lambert { reflectance, transmittance } => {
            let total = reflectance + transmittance;
            if total <= 0.0 {
                return 0.0;
            }
            cosine * if l_in.z > 0.0 { reflectance } else { transmittance } / total
        }
        _ if l_in.z <= 0.0 => 0.0,
        MaterialModel::Mirror { .. } => 0.0,
        MaterialModel::Phong { diffuse, specular, exponent } => {
            let p = diffuse / (diffuse + specular);
            p * cosine + (1.0 - p) * phong::lobe_pdf(exponent, l_in.dot(mirror_image(l)))
        }
        MaterialModel::Ggx { diffuse, specular, roughness } => {
            let p = diffuse / (diffuse + specular);
            p * cosine + (1.0 - p) * ggx_pdf(roughness * roughness, l, l_in)
        }
    }
}

/// Picks `l'` for the outgoing `l` from three uniform numbers; `None` when the path ends
/// (a black material, or a lobe sample below the horizon).
pub fn sample(model: &MaterialModel, l: DVec3, u: [f64; 3]) -> Option<Sample> {
    let l_in = match *model {
        MaterialModel::Lambert { reflectance, transmittance } => {
            let total = reflectance + transmittance;
            if total <= 0.0 {
                return None;
            }
            let d = cosine_direction(u[1], u[2]);
            if u[0] * total < reflectance { d } else { DVec3::new(d.x, d.y, -d.z) }
        }
        MaterialModel::Mirror { reflectance } => {
            let direction = mirror_image(l);
            return (reflectance > 0.0).then_some(Sample { direction, weight: reflectance, pdf: 0.0, delta: true });
        }
        MaterialModel::Phong { diffuse, specular, exponent } => {
            if diffuse + specular <= 0.0 {
                return None;
            }
            if u[0] * (diffuse + specular) < diffuse {
                cosine_direction(u[1], u[2])
            } else {
                let cos_a = phong::lobe_cos(exponent, u[1]);
                Frame::around(mirror_image(l)).world(cone(cos_a, TAU * u[2]))
            }
        }
        MaterialModel::Ggx { diffuse, specular, roughness } => {
            if diffuse + specular <= 0.0 {
                return None;
            }
            if u[0] * (diffuse + specular) < diffuse {
                cosine_direction(u[1], u[2])
            } else {
                let h = ggx::half_vector(roughness * roughness, u[1], TAU * u[2]);
                2.0 * l.dot(h) * h - l
            }
        }
    };
    let density = pdf(model, l, l_in);
    if density <= 0.0 || (l_in.z <= 0.0 && !matches!(model, MaterialModel::Lambert { .. })) {
        return None;
    }
    let weight = evaluate(model, l, l_in) * l_in.z.abs() * FRAC_1_PI / density;
    Some(Sample { direction: l_in, weight, pdf: density, delta: false })
}

/// `D(h) cosθ_h / (4 |l'·h|)`: the density of GGX lobe directions.
fn ggx_pdf(a2: f64, l: DVec3, l_in: DVec3) -> f64 {
    let h = (l + l_in).normalize();
    if h.z <= 0.0 || l.dot(h) <= 0.0 {
        return 0.0;
    }
    ggx::distribution(a2, h.z) * h.z / (4.0 * l_in.dot(h).abs())
}

/// Cosine-distributed direction about `+z` (Malley's method): density `cosθ/π`.
pub fn cosine_direction(u1: f64, u2: f64) -> DVec3 {
    let r = u1.sqrt();
    let phi = TAU * u2;
    DVec3::new(r * phi.cos(), r * phi.sin(), (1.0 - u1).max(0.0).sqrt())
}

/// The direction at polar cosine `cos` and azimuth `phi` about `+z`.
fn cone(cos: f64, phi: f64) -> DVec3 {
    let sin = (1.0 - cos * cos).max(0.0).sqrt();
    DVec3::new(sin * phi.cos(), sin * phi.sin(), cos)
}
