//! The Unified Glare Rating of CIE 117:1995 at an `[[observer]]` (`docs/photometry.md`, "UGR"):
//!
//! `UGR = 8 log10( (0.25 / L_b) Σ_i L_i² ω_i / p_i² )`,
//!
//! over the point luminaires the eye sees in front of it above its line of sight
//! (`guth.rs`) with an unobstructed line to their photometric centre: `L_i = I_i/A_p` the
//! luminance of the luminous opening towards the eye (`crate::luminaire::seen_from`),
//! `ω_i = A_p/r²` its solid angle, `p_i` the Guth position index. The background luminance
//! `L_b = (E − E_direct)/π` is the illuminance at the eye on a plane facing the line of
//! sight, read from the solved field as a point probe's (`correction.rs`), less its direct
//! part. No source in view gives `−∞`; the formula holds for `3·10⁻⁴ < ω < 0.1` sr, and a
//! reading keeps its sources so the caller can warn of those outside.

use crate::luminaire::{Source, seen_from};
use crate::model::Model;
use crate::readout::correction::corrected;
use crate::readout::field::Field;
use crate::readout::guth::position_index;
use crate::scene::Observer;
use crate::visibility::NO_FACE;
use glam::DVec3;
use std::f64::consts::PI;

/// The solid angles within which CIE 117's formula holds, sr.
pub const VALID_SOLID_ANGLE: [f64; 2] = [3e-4, 0.1];

/// A luminaire in an observer's view.
#[derive(Debug, Clone, PartialEq)]
pub struct GlareSource {
    /// The luminaire's name.
    pub name: String,
    /// `L`: its luminance towards the eye, cd/m².
    pub luminance: f64,
    /// `ω`: the solid angle of its luminous opening from the eye, sr.
    pub solid_angle: f64,
    /// `p`: the Guth position index.
    pub position_index: f64,
}

impl GlareSource {
    /// Whether its solid angle lies where the formula holds ([`VALID_SOLID_ANGLE`]).
    pub fn valid(&self) -> bool {
        self.solid_angle > VALID_SOLID_ANGLE[0] && self.solid_angle < VALID_SOLID_ANGLE[1]
    }
}

/// One observer's reading.
#[derive(Debug, Clone, PartialEq)]
pub struct UgrReading {
    /// The observer as described.
    pub observer: Observer,
    /// `L_b`, cd/m².
    pub background: f64,
    /// The luminaires counted, in scene order.
    pub sources: Vec<GlareSource>,
}

impl UgrReading {
    /// The UGR (`−∞` with no source in view).
    pub fn ugr(&self) -> f64 {
        unified_glare_rating(&self.sources, self.background)
    }

    /// The counted sources whose solid angle is outside [`VALID_SOLID_ANGLE`].
    pub fn outside_validity(&self) -> usize {
        self.sources.iter().filter(|s| !s.valid()).count()
    }
}

/// `UGR = 8 log10((0.25 / L_b) Σ L² ω / p²)` over `sources` with the background `L_b`
/// (cd/m²), design.md (5.7): `−∞` with no source.
pub fn unified_glare_rating(sources: &[GlareSource], background: f64) -> f64 {
    let sum: f64 = sources.iter().map(|s| s.luminance * s.luminance * s.solid_angle / s.position_index.powi(2)).sum();
    8.0 * (0.25 * sum / background).log10()
}

/// The point luminaire `source` as the eye at `eye` looking along the unit `look` sees it,
/// obstructions aside: `None` when it is not in front of the eye above its line of sight
/// (`guth.rs`) or sends the eye no light.
pub fn glare_source(source: &Source, eye: DVec3, look: DVec3) -> Option<GlareSource> {
    let seen = seen_from(source, eye)?;
    let r = seen.centre - eye;
    let position_index = position_index(look, r.normalize())?;
    (seen.luminance > 0.0).then(|| GlareSource {
        name: source.name.clone(),
        luminance: seen.luminance,
        solid_angle: seen.area / r.length_squared(),
        position_index,
    })
}

/// Reads every observer from a solved field.
pub fn read_observers(observers: &[Observer], model: &Model, field: &Field) -> Vec<UgrReading> {
    observers.iter().map(|o| read(o, model, field)).collect()
}

fn read(observer: &Observer, model: &Model, field: &Field) -> UgrReading {
    let (eye, look) = (observer.position, observer.look);
    let (e, direct) = corrected(model, field, eye, look).illuminance();
    let sources = model
        .sources
        .iter()
        .filter_map(|source| {
            let glare = glare_source(source, eye, look)?;
            let centre = seen_from(source, eye)?.centre;
            model.visibility.visible(eye, centre, [NO_FACE, NO_FACE]).then_some(glare)
        })
        .collect();
    UgrReading { observer: observer.clone(), background: (e - direct) / PI, sources }
}
