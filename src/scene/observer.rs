//! `[[observer]]` tables: an eye at a point looking along a direction, where the solve
//! reports the Unified Glare Rating of CIE 117:1995 (`docs/photometry.md`, "UGR"). What
//! it reads is `crate::readout::ugr`. Also the `grid` key it shares with `[[glare_grid]]`.

use super::check::{Context, line, number, unique_names};
use super::error::SceneError;
use super::grid::Grid;
use glam::DVec3;
use serde::Deserialize;
use serde_spanned::Spanned;
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
    pub grid: Option<Spanned<String>>,
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
    /// The `[[grid]]` whose UGR it reads: a grid's UGR is the largest of its observers' and
    /// its glare grids' (`crate::readout::grid_ugr`).
    pub grid: Option<String>,
}

/// The smallest angle between the line of sight and the vertical, degrees: the Guth
/// position index needs the vertical plane through the line of sight.
const FROM_VERTICAL_DEG: f64 = 1.0;

/// The observers, each naming an existing grid if any.
pub(super) fn observers(
    path: &Path,
    source: &str,
    raw: &[RawObserver],
    grids: &[Grid],
) -> Result<Vec<Observer>, SceneError> {
    unique_names(path, "observer", raw.iter().map(|o| o.name.as_str()))?;
    raw.iter()
        .enumerate()
        .map(|(index, o)| observer(&Context::item(path, "observer", &o.name, index), source, o, grids))
        .collect()
}

fn observer(at: &Context, source: &str, o: &RawObserver, grids: &[Grid]) -> Result<Observer, SceneError> {
    let position = at.place("position", o.position)?;
    let look = line_of_sight(at, o.look)?;
    let ugr_limit = ugr_limit(at, o.ugr_limit)?;
    let grid = named_grid(at, source, o.grid.as_ref(), grids)?;
    Ok(Observer { name: o.name.clone(), position, look, ugr_limit, grid })
}

/// `grid`: the name of a `[[grid]]` of the case, whose UGR the table's readings count towards.
pub(super) fn named_grid(
    at: &Context,
    source: &str,
    grid: Option<&Spanned<String>>,
    grids: &[Grid],
) -> Result<Option<String>, SceneError> {
    match grid {
        Some(g) if !grids.iter().any(|grid| &grid.name == g.get_ref()) => {
            let message = format!("{}names no [[grid]] of the case: \"{}\"", line(source, g), g.get_ref());
            Err(at.error("grid", message))
        }
        g => Ok(g.map(|g| g.get_ref().clone())),
    }
}

/// `look`: a unit line of sight at least [`FROM_VERTICAL_DEG`] from the vertical.
pub(super) fn line_of_sight(at: &Context, look: [f64; 3]) -> Result<DVec3, SceneError> {
    let look = at.direction("look", look)?;
    if look.y.abs() > FROM_VERTICAL_DEG.to_radians().cos() {
        let message = format!("must be at least {FROM_VERTICAL_DEG}° from the vertical (the line of sight of CIE 117)");
        return Err(at.error("look", message));
    }
    Ok(look)
}

/// `ugr_limit`: EN 12464-1's `UGR_L`, within 0 and 40.
pub(super) fn ugr_limit(at: &Context, limit: Option<f64>) -> Result<Option<f64>, SceneError> {
    let limit = limit.map(|u| at.finite("ugr_limit", u)).transpose()?;
    if let Some(u) = limit.filter(|u| !(0.0..=40.0).contains(u)) {
        return Err(at.error("ugr_limit", format!("must be within 0 and 40, got {}", number(u))));
    }
    Ok(limit)
}
