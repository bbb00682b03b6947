//! A rough look at the light an opening gives a point, for choosing where the hierarchical
//! kernel splits its leaves (`docs/daylight.md`, "Leaves along the openings' light").
//!
//! [`through_window`](super::through_window) cuts the opening until each piece is small
//! and traces each piece's shadows; this looks at the whole opening at once: its
//! unshadowed illuminance at `p` ([`unshadowed`](super::unshadowed), exact for a uniform
//! sky) times the share of [`POINTS`] points spread over the opening through which the ray
//! from `p` leaves the scene. It follows the fall-off with distance exactly and the
//! shadows of reveals and furniture at the spacing of the points, for [`POINTS`] rays.

use super::Opening;
use crate::transfer::occlusion::polygon_points;
use crate::visibility::Sight;
use glam::DVec3;

/// The points looked through: four in each quarter of the opening.
pub const POINTS: usize = 16;

/// The share of the opening's points in front of `p` (unit normal `n`) through which
/// `sight` says the ray from `p` leaves the scene; 1 when none is in front, and without a
/// ray when nothing stands before the whole opening or one occluder hides it all.
pub fn seen_share(opening: &Opening, p: DVec3, n: DVec3, sight: &dyn Sight) -> f64 {
    if sight.clear(&opening.polygon) {
        return 1.0;
    }
    let quarters = opening.polygon.split();
    let points = quarters.iter().flat_map(polygon_points).filter(|x| (*x - p).dot(n) > 0.0);
    let hidden = sight.hidden(&opening.polygon, &mut 0);
    let (seen, all) = points.fold((0, 0), |(seen, all), x| (seen + usize::from(!hidden && sight.sees(x)), all + 1));
    if all == 0 { 1.0 } else { seen as f64 / all as f64 }
}
