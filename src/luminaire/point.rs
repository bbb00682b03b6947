//! The luminaires' direct light at one point, exactly: for a probe, `E = I(w) cosθ / r²`
//! with one shadow ray to the source (parallel light: `E_n cosθ` when a ray towards the sun
//! escapes, times the share the glazed openings it crosses let through, `sky::BeamGlass`), split by the direction cell of `frame` it arrives in. An opening gives the sky
//! and ground through it piece by piece (`crate::sky::through_window`); it has no single
//! direction, so [`incoming`] knows none.

use super::{Light, Source};
use crate::directions::DirectionSet;
use crate::geometry::Frame;
use crate::sky::{Cuts, through_window};
use crate::visibility::{NO_FACE, SightFrom, Visibility};
use glam::DVec3;
use std::f64::consts::PI;

/// The light of `source` at `p` (which lies on face `ignore`, or on none): the unit
/// direction towards the source and the illuminance on a plane facing it, `I(w)/r²` or
/// `E_n` (lx); `None` when the source is hidden or `p` is the source's position.
pub fn incoming(source: &Source, visibility: &Visibility, p: DVec3, ignore: u32) -> Option<(DVec3, f64)> {
    match &source.light {
        Light::Point { position, .. } => {
            let r = p - *position;
            let distance2 = r.length_squared();
            if distance2 <= 0.0 || !visibility.visible(*position, p, [NO_FACE, ignore]) {
                return None;
            }
            let w = r / distance2.sqrt();
            Some((-w, source.intensity(w) / distance2))
        }
        Light::Parallel { direction, illuminance, glass } => {
            let towards = -*direction;
            let escapes = visibility.escapes(p, towards, ignore);
            escapes.then(|| (towards, illuminance * glass.share(p, towards)))
        }
        Light::Window { .. } => None,
    }
}

/// `D_d(p) = E_d(p)/π` per cell of `frame` at `p` (whose receiving side faces
/// `frame.normal`), ignoring the face `ignore` that `p` lies on; an opening's pieces are cut
/// as `cuts` says (`crate::sky::READING` for a reading, coarser where the light is averaged
/// or only guessed).
pub fn arriving_at(
    sources: &[Source],
    visibility: &Visibility,
    directions: &DirectionSet,
    p: DVec3,
    frame: &Frame,
    ignore: u32,
    cuts: Cuts,
) -> Vec<f64> {
    let mut out = vec![0.0; directions.len()];
    let mut arrive = |towards: DVec3, d: f64| out[directions.lookup(frame.local(towards))] += d;
    arriving_along(sources, visibility, p, frame.normal, ignore, cuts, &mut arrive);
    out
}

/// [`arriving_at`] direction by direction: `arrive(towards, dE/π)` for each unit direction
/// `towards` the light comes from onto the side of `p` that `normal` faces.
pub fn arriving_along(
    sources: &[Source],
    visibility: &Visibility,
    p: DVec3,
    normal: DVec3,
    ignore: u32,
    cuts: Cuts,
    arrive: &mut dyn FnMut(DVec3, f64),
) {
    for source in sources {
        let faces = match &source.light {
            Light::Point { position, .. } => (*position - p).dot(normal) > 0.0,
            Light::Parallel { direction, .. } => direction.dot(normal) < 0.0,
            Light::Window { window, sky } => {
                let sight = SightFrom::new(visibility, p, normal, ignore);
                let mut piece = |towards: DVec3, e: f64, _| arrive(towards, e / PI);
                let least = cuts.least(sky, window, p, normal);
                through_window(cuts.eta, sky, window, p, normal, &sight, least, &mut piece);
                false
            }
        };
        if let Some((towards, e)) = faces.then(|| incoming(source, visibility, p, ignore)).flatten() {
            arrive(towards, e * towards.dot(normal) / PI);
        }
    }
}
