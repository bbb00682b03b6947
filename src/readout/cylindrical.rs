//! Cylindrical and semi-cylindrical illuminance at a point (`[[probe]] kind =
//! "cylindrical"`, `"semi_cylindrical"`): the mean illuminance on the curved side of a
//! vanishingly small cylinder (EN 12464-1, `E_z`) or half cylinder (EN 13201-2, `E_sc`)
//! about the unit axis `a`.
//!
//! The curved side's normal at azimuth `φ` is the horizontal (across `a`) unit `h_φ`; its
//! illuminance is the vertical illuminance `E_v(φ) = ∫ L(ω) max(0, ω·h_φ) dω`. Averaged
//! over the azimuths, with `θ` the angle of `ω` from `a` and `ψ` the azimuth of `ω` from
//! the facing direction `h` of the half cylinder:
//!
//! `E_z  = (1/2π) ∫_0^2π E_v dφ = (1/π) ∫ L(ω) sinθ dω`              (the mean of max(0, cos) is 1/π),
//! `E_sc = (1/π) ∫_{−π/2}^{π/2} E_v dφ = (1/π) ∫ L(ω) sinθ (1 + cos ψ) dω`.
//!
//! So a point source of intensity `I` at distance `d` gives `E_z = I sinθ/(π d²)` and
//! `E_sc = I sinθ (1 + cos ψ)/(π d²)` (EN 13201-3's `I (1 + cos α) cos²ε sin ε/(π H²)`),
//! and a uniform enclosure of luminance `L` gives `E_z = E_sc = π L` (`∫ sinθ dω = π²`,
//! `∫ sinθ cosψ dω = 0`). The luminaires' part is exact (`crate::luminaire::incoming`, one
//! shadow ray each, `sinθ (1 + cos ψ) = |ω⊥| + ω·h` with `ω⊥` the part of `ω` across `a`);
//! the surfaces' part is the midpoint rule over [`PLANES`] vertical planes on the circle
//! (half of them on the half circle), each `E_v` gathered from the solved field as a
//! probe's (`gather.rs`): exact for a uniform enclosure; for the light of a small bright
//! patch (the worst case: the rule integrates the kink of `max(0, cos)`) within 0.32 % of
//! `E_z`, and within 0.24 % of the head-on `E_sc`.

use crate::geometry::Frame;
use crate::luminaire::incoming;
use crate::model::Model;
use crate::readout::field::Field;
use crate::readout::gather::gather;
use crate::visibility::NO_FACE;
use glam::DVec3;
use rayon::prelude::*;
use std::f64::consts::PI;

/// Vertical planes over the full circle (a multiple of 4: half of them on a half circle).
pub const PLANES: usize = 32;

/// `(E, its part direct from the luminaires)`, lx, at `p` about the unit `axis`: `E_z`, or
/// with `facing` (a unit vector across the axis) `E_sc`.
pub fn cylindrical(model: &Model, field: &Field, p: DVec3, axis: DVec3, facing: Option<DVec3>) -> (f64, f64) {
    let h = facing.unwrap_or_else(|| Frame::around(axis).tangent);
    let side = axis.cross(h);
    let (start, span, planes) = match facing {
        None => (0.0, 2.0 * PI, PLANES),
        Some(_) => (-PI / 2.0, PI, PLANES / 2),
    };
    let vertical = |k: usize| {
        let phi = start + span * (k as f64 + 0.5) / planes as f64;
        let normal = h * phi.cos() + side * phi.sin();
        PI * gather(model, field, p, &Frame::around(normal), NO_FACE).iter().sum::<f64>()
    };
    let surfaces = (0..planes).into_par_iter().map(vertical).sum::<f64>() / planes as f64;
    let weight = |w: DVec3| {
        let across = (w - axis * w.dot(axis)).length();
        facing.map_or(across, |h| across + w.dot(h)) / PI
    };
    let lit = model.sources.iter().filter_map(|s| incoming(s, &model.visibility, p, NO_FACE));
    let direct = lit.map(|(w, e)| e * weight(w)).sum::<f64>();
    (surfaces + direct, direct)
}
