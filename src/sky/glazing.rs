//! Glazing over an opening: the directional transmittance `τ(θ)` of the glass, a closed set
//! of models selected by `glass` in `[[window]]` (`docs/daylight.md`):
//!
//! * [`Fresnel`] (`glazing_fresnel.rs`, `glass = "fresnel"`, the default when
//!   `transmittance` is given): one or two panes of given normal transmittance;
//! * [`Glazing::Cie171`] (`glazing_cie171.rs`, `glass = "cie171"`): CIE 171's 6 mm clear glass,
//!   the polynomial of its test 5.5.
//!
//! The sky seen through the glazing at incidence `θ` on the opening is the sky times `τ(θ)`:
//! specular transmission, direction by direction (`window.rs`).
//!
//! ```toml
//! [[window]]
//! name = "roof"
//! origin = [1.5, 3.0, 1.5]
//! edge_u = [1.0, 0.0, 0.0]
//! edge_v = [0.0, 0.0, 1.0]
//! glass = "cie171"
//! ```

use super::glazing_cie171;
use super::glazing_fresnel::Fresnel;
use std::fmt;

/// The glass over an opening.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Glazing {
    /// One or two Fresnel panes of given normal transmittance.
    Fresnel(Fresnel),
    /// CIE 171:2006's 6 mm clear glass ("Eq. 19", after Tregenza 1987).
    Cie171,
}

impl Glazing {
    /// `τ(θ)` for `cos` the cosine of the incidence on the opening (its sign ignored).
    pub fn transmittance(&self, cos: f64) -> f64 {
        match self {
            Glazing::Fresnel(panes) => panes.transmittance(cos),
            Glazing::Cie171 => glazing_cie171::transmittance(cos),
        }
    }
}

impl fmt::Display for Glazing {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Glazing::Fresnel(p) => write!(f, "glazed ({} Fresnel pane(s), n = {})", p.panes, p.index),
            Glazing::Cie171 => write!(f, "glazed (CIE 171 6 mm clear glass)"),
        }
    }
}
