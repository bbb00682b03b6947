//! The luminaires as the eye sees them: the luminous opening of every point luminaire
//! (`crate::photometry::LuminousOpening`, from its IES or EULUMDAT file, else a sphere of
//! `FALLBACK_DIAMETER`) placed at its position in its frame, shining towards the eye `l`
//! with the luminance `L(l) = I(l) / A_p(l)`, `A_p` the opening's projected area: the
//! intensity spread evenly over what the eye sees of it (`docs/rendering.md`, `docs/photometry.md`).
//! A dimmed luminaire shows its dimmed intensity; one switched off is black. Only the eye
//! sees the openings (the render's and the traced camera's): the solve, the final gather
//! and the paths take a luminaire as a point.

use super::{Light, Source};
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
            let area = opening.projected_area(frame.local(-direction));
            let luminance = if area > 0.0 { source.intensity(-direction) / area } else { 0.0 };
            nearest = (t, Some(luminance));
        }
    }
    nearest.1
}
