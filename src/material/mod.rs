//! Materials as cell-averaged luminance factors: the blocks of `B` (`design.md` §1, §3).
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
//! material (isotropic models in local frames). Materials never see the scene file.
//! The continuous models' formulas and lobe samplers (`phong`, `ggx`) are public: the Monte
//! Carlo estimators of `crate::trace` use them.

mod block;
mod cells;
pub mod ggx;
mod lambert;
mod mirror;
pub mod phong;

pub use block::Block;
pub use cells::mirror as mirror_image;

use crate::directions::DirectionSet;

/// The closed set of material models, as luminance factors `ρ = π f_r` (`design.md` §1).
#[derive(Debug, Clone, PartialEq)]
pub enum MaterialModel {
    /// Ideal diffuse reflector and (on a two-sided surface) diffuse transmitter:
    /// `ρ ≡ reflectance` on the incident side, `τ ≡ transmittance` on the other;
    /// `reflectance + transmittance ≤ 1`.
    Lambert { reflectance: f64, transmittance: f64 },
    /// Normalized modified Phong (Lafortune & Willems 1994):
    /// `ρ = diffuse + specular · (n + 2)/2 · cosⁿα`, `α` between the outgoing direction
    /// and the mirror image of the incoming one; `diffuse + specular ≤ 1`.
    Phong { diffuse: f64, specular: f64, exponent: f64 },
    /// Ideal specular reflector of reflectance `reflectance`.
    Mirror { reflectance: f64 },
    /// GGX (Trowbridge–Reitz) microfacet reflection with the height-correlated Smith
    /// masking-shadowing term and no Fresnel factor, plus a diffuse part:
    /// `ρ = diffuse + specular · π D(h) G₂ / (4 cosθ cosθ')`, width `roughness` (α).
    Ggx { diffuse: f64, specular: f64, roughness: f64 },
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

}
