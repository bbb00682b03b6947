//! `[[observer]]` tables: an eye at a point looking along a direction, where the solve
//! reports the Unified Glare Rating of CIE 117:1995 (`docs/photometry.md`, "UGR"). What
//! it reads is `crate::readout::ugr`.

use super::check::{Context, number, unique_names};
use super::error::SceneError;
use glam::DVec3;
use serde::Deserialize;
use std::path::Path;

/// `[[observer]]` as written.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawObserver {
    pub name: String,
    #[serde(deserialize_with = "super::arrays::exact")]
    pub position: [f64; 3],
    #[serde(deserialize_with = "super::arrays::exact")]
    pub look: [f64; 3],
    pub ugr_limit: Option<f64>,
}

/// `[[observer]]`: an eye and its line of sight.
#[derive(Debug, Clone, PartialEq)]
pub struct Observer {
    /// The observer's name, unique in the scene.
    pub name: String,
    /// The eye, m.
    pub position: DVec3,
    /// Unit line of sight, not vertical.
    pub look: DVec3,
    /// The UGR the reading is checked against (EN 12464-1's `UGR_L`), if given.
    pub ugr_limit: Option<f64>,
}

/// The smallest angle between the line of sight and the vertical, degrees: the Guth
/// position index needs the vertical plane through the line of sight.
const FROM_VERTICAL_DEG: f64 = 1.0;

pub(super) fn observers(path: &Path, raw: &[RawObserver]) -> Result<Vec<Observer>, SceneError> {
    unique_names(path, "observer", raw.iter().map(|o| o.name.as_str()))?;
    raw.iter().enumerate().map(|(index, o)| observer(&Context::item(path, "observer", &o.name, index), o)).collect()
}

fn observer(at: &Context, o: &RawObserver) -> Result<Observer, SceneError> {
    let position = at.place("position", o.position)?;
    let look = at.direction("look", o.look)?;
    if look.y.abs() > FROM_VERTICAL_DEG.to_radians().cos() {
        let message = format!("must be at least {FROM_VERTICAL_DEG}° from the vertical (the line of sight of CIE 117)");
        return Err(at.error("look", message));
    }
    let ugr_limit = o.ugr_limit.map(|u| at.finite("ugr_limit", u)).transpose()?;
    if let Some(u) = ugr_limit.filter(|u| !(0.0..=40.0).contains(u)) {
        return Err(at.error("ugr_limit", format!("must be within 0 and 40, got {}", number(u))));
    }
    Ok(Observer { name: o.name.clone(), position, look, ugr_limit })
}
