//! A luminaire as described (`[[luminaire]]`, validated): its kind, placement, aim and
//! distribution, before it is placed in a frame (`Source`). The scene file is validated
//! into these; nothing here sees TOML.

use crate::photometry::Distribution;
use crate::sky::{BeamGlass, Opening, Sky};
use glam::DVec3;
use std::path::PathBuf;

/// `[[luminaire]]`: a light source outside the unknowns of the system.
#[derive(Debug, Clone, PartialEq)]
pub struct Luminaire {
    /// The luminaire's name, unique in the scene.
    pub name: String,
    /// What kind of light it is.
    pub kind: LuminaireKind,
}

/// The closed set of luminaire kinds.
#[derive(Debug, Clone, PartialEq)]
pub enum LuminaireKind {
    /// A point source with an intensity distribution, placed and aimed.
    Point(PointLuminaire),
    /// Parallel light (the sun): unit direction of travel and illuminance normal to the beam, lx.
    Parallel {
        /// Unit direction of travel.
        direction: DVec3,
        /// Illuminance normal to the beam, lx.
        illuminance: f64,
        /// The glazed openings it may pass, which attenuate it (the scene's `[[window]]`s).
        glass: BeamGlass,
    },
    /// An opening (`[[window]]`): the sky and the ground seen through the polygon.
    Window {
        /// The opening.
        window: Opening,
        /// The sky and ground seen through it.
        sky: Sky,
    },
}

/// A photometric point source.
#[derive(Debug, Clone, PartialEq)]
pub struct PointLuminaire {
    /// m.
    pub position: DVec3,
    /// Unit aiming direction: γ = 0 of the distribution (default straight down).
    pub aim: DVec3,
    /// Turn of the C0 axis about the aim, degrees, counter-clockwise seen from behind.
    pub rotate_deg: f64,
    /// Maintenance or dimming factor on every intensity.
    pub multiplier: f64,
    /// The luminous intensity distribution in the luminaire frame, cd.
    pub distribution: Distribution,
    /// The photometric file, when the distribution was read from one.
    pub file: Option<PathBuf>,
}
