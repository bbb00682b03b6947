//! The openings' light at a point (`docs/daylight.md`): the sky and the ground seen through
//! every `[[window]]`, piece by piece exactly as the source term takes them
//! (`crate::sky::through_window`, one ray per test point); the sky component SC and the
//! externally reflected component ERC of a point sensor, and of each vertical plane of a
//! cylindrical probe (`cylindrical.rs`).

use crate::geometry::Frame;
use crate::luminaire::Light;
use crate::model::Model;
use crate::sky::{Component, ETA, through_window};
use crate::visibility::NO_FACE;
use glam::DVec3;

/// The illuminance (lx) at `p` (receiving side facing the unit `n`) from the sky and from
/// the ground through every opening of the model: `(SC, ERC)` in lx.
pub fn sky_and_ground(model: &Model, p: DVec3, n: DVec3) -> (f64, f64) {
    let patch = model.faces.under(&model.mesh, &model.visibility, p, n);
    let ignore = patch.map_or(NO_FACE, |i| model.mesh.patches[i].face);
    let normal = patch.map_or_else(|| Frame::around(n), |i| model.mesh.patches[i].frame()).normal;
    let sees = |x: DVec3| model.visibility.closest_hit(p, x - p, ignore).is_none();
    let (mut sky, mut ground) = (0.0, 0.0);
    for source in &model.sources {
        if let Light::Window { window, sky: outside } = &source.light {
            through_window(ETA, outside, window, p, normal, &sees, 0.0, &mut |_, e, component| match component {
                Component::Sky => sky += e,
                Component::Ground => ground += e,
            });
        }
    }
    (sky, ground)
}
