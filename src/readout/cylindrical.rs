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
//! `E_z`, and within 0.24 % of the head-on `E_sc`. The openings' light (the sky and the
//! ground through them, `openings.rs`) is taken on the same
//! vertical planes, exactly on each: it is part of the direct light, and the daylight
//! components SC and ERC of such a probe are its two parts (so `DF = SC + ERC + IRC`).

use crate::geometry::Frame;
use crate::luminaire::incoming;
use crate::model::Model;
use crate::readout::field::Field;
use crate::readout::gather::gather;
use crate::readout::openings::sky_and_ground;
use crate::visibility::NO_FACE;
use glam::DVec3;
use rayon::prelude::*;
use std::f64::consts::PI;

/// Vertical planes over the full circle (a multiple of 4: half of them on a half circle).
pub const PLANES: usize = 32;

/// `(E, its part direct from the sources)`, lx, at `p` about the unit `axis`: `E_z`, or
/// with `facing` (a unit vector across the axis) `E_sc`.
pub fn cylindrical(model: &Model, field: &Field, p: DVec3, axis: DVec3, facing: Option<DVec3>) -> (f64, f64) {
    let normals = planes(axis, facing);
    let vertical = |n: &DVec3| PI * gather(model, field, p, &Frame::around(*n), NO_FACE).iter().sum::<f64>();
    let surfaces = normals.par_iter().map(vertical).sum::<f64>() / normals.len() as f64;
    let weight = |w: DVec3| {
        let across = (w - axis * w.dot(axis)).length();
        facing.map_or(across, |h| across + w.dot(h)) / PI
    };
    let lit = model.sources.iter().filter_map(|s| incoming(s, &model.visibility, p, NO_FACE));
    let (sky, ground) = openings(model, p, axis, facing);
    let direct = lit.map(|(w, e)| e * weight(w)).sum::<f64>() + sky + ground;
    (surfaces + direct, direct)
}

/// The openings' light at `p` on the cylinder (or half cylinder): `(sky, ground)`, lx, the
/// mean over the vertical planes of what each receives through every opening.
pub fn openings(model: &Model, p: DVec3, axis: DVec3, facing: Option<DVec3>) -> (f64, f64) {
    let normals = planes(axis, facing);
    let (sky, ground) =
        normals.par_iter().map(|&n| sky_and_ground(model, p, n)).reduce(|| (0.0, 0.0), |a, b| (a.0 + b.0, a.1 + b.1));
    (sky / normals.len() as f64, ground / normals.len() as f64)
}

/// The normals of the vertical planes of the midpoint rule: [`PLANES`] over the circle
/// about `axis`, or half of them over the half circle centred on `facing`.
pub fn planes(axis: DVec3, facing: Option<DVec3>) -> Vec<DVec3> {
    let h = facing.unwrap_or_else(|| Frame::around(axis).tangent);
    let side = axis.cross(h);
    let (start, span, planes) = match facing {
        None => (0.0, 2.0 * PI, PLANES),
        Some(_) => (-PI / 2.0, PI, PLANES / 2),
    };
    (0..planes)
        .map(|k| {
            let phi = start + span * (k as f64 + 0.5) / planes as f64;
            h * phi.cos() + side * phi.sin()
        })
        .collect()
}
