//! Luminaires in the system: their direct light as the source term of the patches it
//! reaches (`docs/design.md` §1, §3):
//!
//! `L0(i,k) = L_e(i) + Σ_d ρ̄_i(k,d) D(i,d)`,   `D(i,d) = E_s(i,d)/π`,
//!
//! where `E_s(i,d)` is the illuminance from the luminaires averaged over patch `i`
//! (shadows included, rays through the BVH), split by the direction cell `d` of the
//! patch's frame that the light arrives in. `D` has the units of the transport `G x`
//! (`E = π Σ_d`), so the materials act on it exactly as on light from surfaces, through the
//! same blocks `B` (transmission to the twin included): glossy receivers reflect the
//! luminaire's light towards the mirror direction. Luminaires are not unknowns.
//!
//! Owns the luminaires as described (`description.rs`), the placed sources ([`Source`]: a point source's frame from its aim, its
//! multiplier and tilt factor; parallel light), the patch-averaged illuminance
//! (`patch.rs`), the exact illuminance at a point for probes (`point.rs`) and the luminance
//! of the luminous openings the eye sees (`seen.rs`). An opening
//! (`[[window]]`) is a source too: the sky and the ground seen through it (`crate::sky`).

mod aim;
mod description;
mod patch;
mod point;
mod seen;

pub use aim::frame;
pub use description::{Luminaire, LuminaireKind, PointLuminaire};
pub use patch::{DirectLight, OPENING_ETA, PatchLight, direct_light, patch_lights};
pub use point::{arriving_along, arriving_at, incoming};
pub use seen::{Shining, luminous_along, seen_from};

use crate::geometry::Frame;
use crate::photometry::Distribution;
use crate::sky::{BeamGlass, Opening, Sky};
use glam::DVec3;

/// A luminaire placed in the scene.
#[derive(Debug, Clone, PartialEq)]
pub struct Source {
    /// The luminaire's name.
    pub name: String,
    /// Its light as placed.
    pub light: Light,
    /// The factor a light scene dimmed it by (1 as placed). Its light on the patches is
    /// cut along shadows as its undimmed light would be (`patch_lights`), so that it is
    /// exactly this factor times its own.
    pub dimmed: f64,
}

/// The closed set of sources.
#[derive(Debug, Clone, PartialEq)]
pub enum Light {
    /// Intensity `scale · I(frame.local(w))` towards the world direction `w` from `position`.
    Point {
        /// The source's position, m.
        position: DVec3,
        /// The luminaire frame, from the aim and the rotation.
        frame: Frame,
        /// The intensity distribution in that frame, cd.
        distribution: Distribution,
        /// Multiplier times tilt factor.
        scale: f64,
    },
    /// Illuminance `illuminance` normal to a beam travelling along `direction`, times the
    /// share `glass` lets through where the beam crosses glazed openings.
    Parallel {
        /// Unit direction of travel.
        direction: DVec3,
        /// Illuminance normal to the beam, lx.
        illuminance: f64,
        /// The glazed openings it may pass.
        glass: BeamGlass,
    },
    /// The sky and the ground seen through the opening `window` (`crate::sky`).
    Window {
        /// The opening.
        window: Opening,
        /// The sky and ground seen through it.
        sky: Sky,
    },
}

impl Source {
    /// The source of a validated `[[luminaire]]`: frame from the aim and rotation, scale =
    /// multiplier × the file's tilt factor at the luminaire's tilt.
    pub fn of(luminaire: &Luminaire) -> Source {
        let light = match &luminaire.kind {
            LuminaireKind::Point(p) => {
                let frame = frame(p.aim, p.rotate_deg);
                let tilt = match &p.distribution {
                    Distribution::Table(t) => t
                        .tilt
                        .as_ref()
                        .map_or(1.0, |tilt| tilt.factor(tilt.angle(frame.tangent, frame.bitangent, frame.normal))),
                    _ => 1.0,
                };
                Light::Point {
                    position: p.position,
                    frame,
                    distribution: p.distribution.clone(),
                    scale: p.multiplier * tilt,
                }
            }
            LuminaireKind::Parallel { direction, illuminance, glass } => {
                Light::Parallel { direction: *direction, illuminance: *illuminance, glass: glass.clone() }
            }
            LuminaireKind::Window { window, sky } => Light::Window { window: *window, sky: sky.clone() },
        };
        Source { name: luminaire.name.clone(), light, dimmed: 1.0 }
    }

    /// The same source with every intensity (or the parallel light's illuminance) times
    /// `factor`: dimmed.
    pub fn scaled(&self, factor: f64) -> Source {
        let light = match &self.light {
            Light::Point { position, frame, distribution, scale } => Light::Point {
                position: *position,
                frame: *frame,
                distribution: distribution.clone(),
                scale: scale * factor,
            },
            Light::Parallel { direction, illuminance, glass } => {
                Light::Parallel { direction: *direction, illuminance: illuminance * factor, glass: glass.clone() }
            }
            Light::Window { window, sky } => Light::Window { window: *window, sky: sky.scaled(factor) },
        };
        Source { name: self.name.clone(), light, dimmed: self.dimmed * factor }
    }

    /// The flux leaving a point source, lm; none for parallel light (an unbounded beam)
    /// and an opening.
    pub fn flux(&self) -> Option<f64> {
        match &self.light {
            Light::Point { distribution, scale, .. } => Some(scale * distribution.flux()),
            Light::Parallel { .. } | Light::Window { .. } => None,
        }
    }

    /// True when a plane mirror's reflection of this source's light is an image source
    /// (`docs/mirrors.md`): a point source's is; parallel light's and an opening's are not
    /// carried that way, so a scene lit by them keeps its mirrors' cell blocks.
    pub fn mirrored_by_image(&self) -> bool {
        matches!(self.light, Light::Point { .. })
    }

    /// The intensity of a point source towards the unit world direction `w`, cd.
    pub fn intensity(&self, w: DVec3) -> f64 {
        match &self.light {
            Light::Point { frame, distribution, scale, .. } => scale * distribution.intensity(frame.local(w)),
            Light::Parallel { .. } | Light::Window { .. } => 0.0,
        }
    }
}
