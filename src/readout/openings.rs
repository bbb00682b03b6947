//! The openings' light at a point (`docs/daylight.md`): the sky and the ground seen through
//! every `[[window]]`, piece by piece exactly as the source term takes them
//! (`crate::sky::through_window`, one ray per test point); the sky component SC and the
//! externally reflected component ERC of a point sensor, and of each vertical plane of a
//! cylindrical probe (`cylindrical.rs`).

use crate::luminaire::Light;
use crate::model::Model;
use crate::readout::gather::Receiver;
use crate::sky::{Component, ETA, through_window};
use crate::visibility::SightFrom;
use glam::DVec3;

/// The illuminance (lx) at `p` (receiving side facing the unit `n`) from the sky and from
/// the ground through every opening of the model: `(SC, ERC)` in lx.
pub fn sky_and_ground(model: &Model, p: DVec3, n: DVec3) -> (f64, f64) {
    let Receiver { frame, ignore, .. } = Receiver::at(model, p, n);
    let normal = frame.normal;
    let (mut sky, mut ground) = (0.0, 0.0);
    for source in &model.sources {
        if let Light::Window { window, sky: outside } = &source.light {
            let sight = SightFrom::new(&model.visibility, p, normal, ignore);
            through_window(ETA, outside, window, p, normal, &sight, 0.0, &mut |_, e, component| match component {
                Component::Sky => sky += e,
                Component::Ground => ground += e,
            });
        }
    }
    (sky, ground)
}
