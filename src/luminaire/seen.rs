//! The luminaires as the eye sees them: the luminous opening of every point luminaire
//! (`crate::photometry::LuminousOpening`, from its IES or EULUMDAT file, else a sphere of
//! `FALLBACK_DIAMETER`) placed at its position in its frame, shining towards the eye `l`
//! with the luminance `L(l) = I(l) / A_p(l)`, `A_p` the opening's projected area: the
//! intensity spread evenly over what the eye sees of it (`docs/rendering.md`, `docs/photometry.md`).
//! A dimmed luminaire shows its dimmed intensity; one switched off is black. Only the eye
//! sees the openings (the render's and the traced camera's, along a ray: [`luminous_along`];
//! an observer's glare, whole: [`seen_from`], `crate::readout::ugr`): the solve, the final
//! gather and the paths take a luminaire as a point.

use super::{Light, Source};
use crate::geometry::Frame;
use crate::photometry::LuminousOpening;
use glam::DVec3;

/// The luminance of the nearest luminous opening along the unit `direction` from
/// `origin`, if one lies nearer than `before` (m), cd/m².
pub fn luminous_along(sources: &[Source], origin: DVec3, direction: DVec3, before: f64) -> Option<f64> {
    let mut nearest = (before, None);
    for source in sources {
        let Light::Point { position, frame, distribution, .. } = &source.light else { continue };
        let opening = distribution.luminous();
        let Some(t) = opening.entry(frame.local(origin - *position), frame.local(direction)) else { continue };
        if t < nearest.0 {
            nearest = (t, Some(shining(source, *position, &opening, frame, -direction).luminance));
        }
    }
    nearest.1
}

/// A luminous opening as an eye sees it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Shining {
    /// The photometric centre, m.
    pub centre: DVec3,
    /// The opening's area projected across the view, `A_p`, m².
    pub area: f64,
    /// `L = I/A_p` towards the eye, cd/m² (0 for an opening seen edge-on).
    pub luminance: f64,
}

/// The opening of a point luminaire as seen from the eye at `eye`, taken along the line
/// from its photometric centre; `None` for parallel light and openings (windows).
pub fn seen_from(source: &Source, eye: DVec3) -> Option<Shining> {
    let Light::Point { position, frame, distribution, .. } = &source.light else { return None };
    let towards = (eye - *position).try_normalize()?;
    Some(shining(source, *position, &distribution.luminous(), frame, towards))
}

/// `source`'s opening (centred on `centre`, in its `frame`) seen along the unit world direction `towards` the eye.
fn shining(source: &Source, centre: DVec3, opening: &LuminousOpening, frame: &Frame, towards: DVec3) -> Shining {
    let area = opening.projected_area(frame.local(towards));
    let luminance = if area > 0.0 { source.intensity(towards) / area } else { 0.0 };
    Shining { centre, area, luminance }
}
