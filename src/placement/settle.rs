//! A spot moved along its surface to a distance from the planes of one or two walls, and
//! checked there: the point still lies on a surface of the spot's plane, so does the way
//! from it to each wall's foot (the wall meets the surface: a concave edge, not a gap), a
//! ray along the surface meets each wall at the distance, and nothing lies on the surface
//! at the point (a solid standing on it).

use super::around::{OFFSET, Spot, Wall};
use super::sight::Sight;
use glam::DVec3;

/// The spot moved along its surface to `distance` (m) from the plane of every wall of
/// `walls` (one or two), if the walls are there and the surface reaches them.
pub fn settle(sight: &Sight, spot: &Spot, walls: &[Wall], distance: f64) -> Option<Spot> {
    let n = spot.normal();
    let across: Vec<DVec3> = walls.iter().map(|w| w.normal - n * w.normal.dot(n)).collect();
    let point = match (walls, across.as_slice()) {
        ([w], [g]) => spot.point + *g * ((distance - w.distance) / g.length_squared()),
        ([a, b], [ga, gb]) => {
            let (t, s) = (spot.frame.tangent, spot.frame.bitangent);
            let det = ga.dot(t) * gb.dot(s) - ga.dot(s) * gb.dot(t);
            if det.abs() < 0.3 {
                return None;
            }
            let (ca, cb) = (distance - a.distance, distance - b.distance);
            let alpha = (ca * gb.dot(s) - cb * ga.dot(s)) / det;
            let beta = (cb * ga.dot(t) - ca * gb.dot(t)) / det;
            spot.point + t * alpha + s * beta
        }
        _ => return None,
    };
    let patch = sight.on_plane(point, n)?;
    let moved = Spot { patch, face: sight.world.mesh.patches[patch].face, ..spot.moved(point) };
    let reaches = walls.iter().zip(&across).all(|(w, g)| reaches(sight, &moved, w, *g, distance));
    let ahead = sight.first(point, n, moved.face);
    (reaches && ahead.is_none_or(|s| s.distance > 2e-3 && s.patch.is_some())).then_some(moved)
}

/// True when the surface runs from `spot` to the foot of `wall` (`g` its normal's part
/// along the surface) and a ray along the surface meets the wall at `distance` from its
/// plane.
fn reaches(sight: &Sight, spot: &Spot, wall: &Wall, g: DVec3, distance: f64) -> bool {
    let (towards, run) = (-g.normalize(), distance / g.length());
    let n = spot.normal();
    let on_surface = [0.5, 0.9].iter().all(|f| sight.on_plane(spot.point + towards * (run * f), n).is_some());
    let Some(seen) = sight.first(spot.point + n * OFFSET, towards, spot.face) else { return false };
    let meets = seen.patch.is_some_and(|p| sight.normal(p).dot(wall.normal) > 0.99);
    on_surface && meets && (seen.distance - run).abs() < 0.05 * run + 1e-3
}
