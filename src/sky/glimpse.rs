//! A rough look at the light an opening gives a point, for choosing where the hierarchical
//! kernel splits its leaves (`docs/daylight.md`, "Leaves along the openings' light").
//!
//! [`through_window`](super::through_window) cuts the opening until each piece is small
//! and traces each piece's shadows; this looks at the whole opening at once. Its
//! unshadowed illuminance at `p` is, per part above and below the horizontal plane through
//! `p`, the part's projected solid angle (exact, Lambert's contour integral) times the sky's
//! or the ground's luminance towards the part's centre (through the glass); the shadowed
//! one is that times the share of [`POINTS`] points spread over the opening through which
//! the ray from `p` leaves the scene. It follows the fall-off with distance exactly and the
//! shadows of reveals and furniture at the spacing of the points, for [`POINTS`] rays.

use super::window::for_each_part;
use super::{Opening, Sky};
use crate::transfer::contour::projected_solid_angle;
use crate::transfer::occlusion::polygon_points;
use glam::DVec3;

/// The points looked through: four in each quarter of the opening.
pub const POINTS: usize = 16;

/// The illuminance (lx) the opening gives the plane of `p` (unit normal `n`) with nothing in
/// the way but the opening's own edges.
pub fn unshadowed(sky: &Sky, opening: &Opening, p: DVec3, n: DVec3) -> f64 {
    let mut e = 0.0;
    for_each_part(&opening.polygon, p, n, &mut |part, _| {
        e += luminance(sky, opening, part.centroid() - p) * projected_solid_angle(p, n, part.vertices()).abs();
    });
    e
}

/// The share of the opening's points in front of `p` (unit normal `n`) through which `sees`
/// says the ray from `p` leaves the scene; 1 when none is in front.
pub fn seen_share(opening: &Opening, p: DVec3, n: DVec3, sees: &dyn Fn(DVec3) -> bool) -> f64 {
    let quarters = opening.polygon.split();
    let points = quarters.iter().flat_map(polygon_points).filter(|x| (*x - p).dot(n) > 0.0);
    let (seen, all) = points.fold((0, 0), |(seen, all), x| (seen + usize::from(sees(x)), all + 1));
    if all == 0 { 1.0 } else { seen as f64 / all as f64 }
}

/// The outside's luminance along `towards` through the opening (cd/m²): the sky above the
/// horizon, the ground below, times the glass's `τ(θ)`.
fn luminance(sky: &Sky, opening: &Opening, towards: DVec3) -> f64 {
    let l = towards.normalize_or_zero();
    let outside = sky.luminance(l);
    opening.glazing.map_or(outside, |g| outside * g.transmittance(l.dot(opening.polygon.normal())))
}
