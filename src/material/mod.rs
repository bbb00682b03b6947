//! Materials as cell-averaged luminance factors: the blocks of `B` (`docs/design.md` §1, §3).
//!
//! A block holds, for outgoing cell `k` and incoming cell `d`, the luminance factor
//! averaged over both cells with the projected-solid-angle measure,
//!
//! `ρ̄(k,d) = (1/(μ_k μ_d)) ∫_{C_k} ∫_{C_d} ρ(l, l') cosθ cosθ' dω' dω`,
//!
//! which keeps reciprocity (`ρ̄(k,d) = ρ̄(d,k)` when `ρ(l,l') = ρ(l',l)`) and energy: the
//! albedo of incoming cell `d`, `a(d) = (1/π) Σ_k ρ̄(k,d) μ_k`, is the cos-weighted mean
//! over the cell of the directional-hemispherical reflectance. A transmitting material
//! has a second block for light arriving on the other side of a two-sided surface
//! (incoming cell in the back patch's frame). Blocks are shared by every patch of one
//! material (isotropic models in local frames).
//!
//! Each model is one file (`lambert`, `phong`, `mirror`, `ggx`) holding its luminance
//! factor, its cell block, its sampler and density for the Monte Carlo estimators
//! (`crate::trace`; by reciprocity the same sampler serves paths from the eye and from the
//! source), the keys that select it and a TOML example in its module documentation.
//! [`MaterialModel`] is the closed set, dispatched once per operation here. Materials never
//! see the scene file: `crate::scene` validates the keys into a `MaterialModel`.

mod block;
mod cells;
mod colour;
pub mod ggx;
pub mod lambert;
pub mod mirror;
pub mod phong;
mod sample;

pub use block::Block;
pub use colour::{LUMINANCE_WEIGHTS, linear_of_srgb, reflectance_of_colour};
pub use sample::Sample;

use crate::directions::DirectionSet;
use glam::DVec3;
use std::f64::consts::{FRAC_1_PI, FRAC_PI_2, SQRT_2};

/// The models by name: what a `type` selects, matched exhaustively where its keys are read.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// [`lambert`].
    Lambert,
    /// [`phong`].
    Phong,
    /// [`mirror`].
    Mirror,
    /// [`ggx`].
    Ggx,
}

impl Kind {
    /// Every model, in the order the documentation lists them.
    pub const ALL: [Kind; 4] = [Kind::Lambert, Kind::Phong, Kind::Mirror, Kind::Ggx];

    /// The model's `type`.
    pub fn name(self) -> &'static str {
        match self {
            Kind::Lambert => lambert::TYPE,
            Kind::Phong => phong::TYPE,
            Kind::Mirror => mirror::TYPE,
            Kind::Ggx => ggx::TYPE,
        }
    }

    /// The keys the model takes.
    pub fn keys(self) -> &'static [&'static str] {
        match self {
            Kind::Lambert => lambert::KEYS,
            Kind::Phong => phong::KEYS,
            Kind::Mirror => mirror::KEYS,
            Kind::Ggx => ggx::KEYS,
        }
    }

    /// The model named `name`, if any.
    pub fn parse(name: &str) -> Option<Kind> {
        Kind::ALL.into_iter().find(|k| k.name() == name)
    }
}

/// The closed set of material models, as luminance factors `ρ = π f_r` (`docs/design.md` §1).
#[derive(Debug, Clone, PartialEq)]
pub enum MaterialModel {
    /// Ideal diffuse reflector and (on a two-sided surface) diffuse transmitter:
    /// `ρ ≡ reflectance` on the incident side, `τ ≡ transmittance` on the other;
    /// `reflectance + transmittance ≤ 1`.
    Lambert {
        /// Reflectance `r`, the luminance factor on the incident side.
        reflectance: f64,
        /// Diffuse transmittance `t`, the luminance factor through to the other side.
        transmittance: f64,
    },
    /// Normalized modified Phong (Lafortune & Willems 1994):
    /// `ρ = diffuse + specular · (n + 2)/2 · cosⁿα`, `α` between the outgoing direction
    /// and the mirror image of the incoming one; `diffuse + specular ≤ 1`.
    Phong {
        /// Diffuse part `k_d`.
        diffuse: f64,
        /// Specular weight `k_s`.
        specular: f64,
        /// Lobe exponent `n`.
        exponent: f64,
    },
    /// Ideal specular reflector of reflectance `reflectance`.
    Mirror {
        /// Specular reflectance `ρ_s`.
        reflectance: f64,
    },
    /// GGX (Trowbridge–Reitz) microfacet reflection with the height-correlated Smith
    /// masking-shadowing term and no Fresnel factor, plus a diffuse part:
    /// `ρ = diffuse + specular · π D(h) G₂ / (4 cosθ cosθ')`, width `roughness` (α).
    Ggx {
        /// Diffuse part `k_d`.
        diffuse: f64,
        /// Specular weight `k_s`.
        specular: f64,
        /// GGX width `α`.
        roughness: f64,
    },
}

impl MaterialModel {
    /// The cell-averaged luminance factor of this model on `directions`.
    pub fn block(&self, directions: &DirectionSet) -> Block {
        let k = directions.len();
        let (reflect, transmit) = match *self {
            MaterialModel::Lambert { reflectance, transmittance } => {
                (lambert::block(reflectance, k), (transmittance > 0.0).then(|| lambert::block(transmittance, k)))
            }
            MaterialModel::Phong { diffuse, specular, exponent } => {
                (phong::block(diffuse, specular, exponent, directions), None)
            }
            MaterialModel::Mirror { reflectance } => (mirror::block(reflectance, directions), None),
            MaterialModel::Ggx { diffuse, specular, roughness } => {
                (ggx::block(diffuse, specular, roughness, directions), None)
            }
        };
        Block::new(k, reflect, transmit)
    }

    /// True when light also passes through to the other side of a two-sided surface.
    pub fn transmits(&self) -> bool {
        matches!(*self, MaterialModel::Lambert { transmittance, .. } if transmittance > 0.0)
    }

    /// The half width at half maximum of its glossy lobe, rad: how far from the lobe's axis
    /// the outgoing direction turns before the specular part halves (Phong's `cosⁿα = 1/2`;
    /// GGX's `D(h)` halved at `tan²θ_h = (√2 − 1)α²/(1 − √2 α²)`, and the reflected direction
    /// turns by `2θ_h`), at most π/2 (a lobe so wide covers the hemisphere). `None` for a
    /// Lambertian surface and a mirror, which have no lobe.
    pub fn lobe_width(&self) -> Option<f64> {
        match *self {
            MaterialModel::Phong { exponent, .. } => Some(0.5f64.powf(1.0 / exponent).acos()),
            MaterialModel::Ggx { roughness, .. } => {
                let a2 = roughness * roughness;
                let t = (SQRT_2 - 1.0) * a2 / (1.0 - SQRT_2 * a2);
                Some(if t > 0.0 { (2.0 * t.sqrt().atan()).min(FRAC_PI_2) } else { FRAC_PI_2 })
            }
            MaterialModel::Lambert { .. } | MaterialModel::Mirror { .. } => None,
        }
    }

    /// True when the material scatters into a single direction (no next-event estimation).
    pub fn is_delta(&self) -> bool {
        matches!(self, MaterialModel::Mirror { .. })
    }

    /// The luminance factor `ρ(l, l')` of local directions (`l.z > 0`), or `τ` through the
    /// surface (`l'.z < 0`, Lambert only).
    pub fn luminance_factor(&self, l: DVec3, l_in: DVec3) -> f64 {
        match *self {
            MaterialModel::Lambert { reflectance, transmittance } => {
                lambert::luminance_factor(reflectance, transmittance, l_in)
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

    /// Density per solid angle with which [`MaterialModel::sample`] picks `l'` given `l`.
    pub fn pdf(&self, l: DVec3, l_in: DVec3) -> f64 {
        match *self {
            MaterialModel::Lambert { reflectance, transmittance } => lambert::pdf(reflectance, transmittance, l_in),
            _ if l_in.z <= 0.0 => 0.0,
            MaterialModel::Mirror { .. } => 0.0,
            MaterialModel::Phong { diffuse, specular, exponent } => phong::pdf(diffuse, specular, exponent, l, l_in),
            MaterialModel::Ggx { diffuse, specular, roughness } => ggx::pdf(diffuse, specular, roughness, l, l_in),
        }
    }

    /// Picks `l'` for the outgoing `l` from three uniform numbers, importance-sampling
    /// `(1/π) ρ(l, l') |cosθ'|`; `None` when the path ends (a black material, or a lobe
    /// sample below the horizon).
    pub fn sample(&self, l: DVec3, u: [f64; 3]) -> Option<Sample> {
        let l_in = match *self {
            MaterialModel::Lambert { reflectance, transmittance } => lambert::sample(reflectance, transmittance, u)?,
            MaterialModel::Mirror { reflectance } => return mirror::sample(reflectance, l),
            MaterialModel::Phong { diffuse, specular, exponent } => phong::sample(diffuse, specular, exponent, l, u)?,
            MaterialModel::Ggx { diffuse, specular, roughness } => ggx::sample(diffuse, specular, roughness, l, u)?,
        };
        let density = self.pdf(l, l_in);
        if density <= 0.0 || (l_in.z <= 0.0 && !matches!(self, MaterialModel::Lambert { .. })) {
            return None;
        }
        let weight = self.luminance_factor(l, l_in) * l_in.z.abs() * FRAC_1_PI / density;
        Some(Sample { direction: l_in, weight, pdf: density, delta: false })
    }
}
