//! What a material's sampler returns: an incoming direction with its weight and density.

use glam::DVec3;

/// One sampled incoming direction, in the patch's local frame.
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
