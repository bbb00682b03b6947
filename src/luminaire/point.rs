//! The luminaires' direct light at one point, exactly: for a probe, `E = I(w) cosθ / r²`
//! with one shadow ray to the source (parallel light: `E_n cosθ` when a ray towards the sun
//! escapes), split by the direction cell of `frame` it arrives in.

use super::{Light, Source};
use crate::directions::DirectionSet;
use crate::geometry::Frame;
use crate::visibility::{NO_FACE, Visibility};
use glam::DVec3;
use std::f64::consts::PI;

/// `D_d(p) = E_d(p)/π` per cell of `frame` at `p` (whose receiving side faces
/// `frame.normal`), ignoring the face `ignore` that `p` lies on.
pub fn arriving_at(
    sources: &[Source],
    visibility: &Visibility,
    directions: &DirectionSet,
    p: DVec3,
    frame: &Frame,
    ignore: u32,
) -> Vec<f64> {
    let mut out = vec![0.0; directions.len()];
    for source in sources {
        let (towards_source, illuminance) = match &source.light {
            Light::Point { position, .. } => {
                let r = p - *position;
                let distance = r.length();
                let w = r / distance;
                let cos = -w.dot(frame.normal);
                if cos.is_nan() || cos <= 0.0 || !visibility.visible(*position, p, [NO_FACE, ignore]) {
                    continue;
                }
                (-w, source.intensity(w) * cos / (distance * distance))
            }
            Light::Parallel { direction, illuminance } => {
                let cos = -direction.dot(frame.normal);
                if cos <= 0.0 || visibility.closest_hit(p, -*direction, ignore).is_some() {
                    continue;
                }
                (-*direction, illuminance * cos)
            }
        };
        out[directions.lookup(frame.local(towards_source))] += illuminance / PI;
    }
    out
}
