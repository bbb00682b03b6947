//! `[[glare_grid]]` tables: observers on a grid of eye positions, each looking along one or
//! more lines of sight turned about the vertical at a fixed angular step, where the solve
//! reports the UGR of CIE 117 per position and view and the largest against `ugr_limit`
//! (EN 12464-1's practice; `docs/photometry.md`, "UGR on a grid of observers"), and the
//! `[[grid]]` whose UGR its readings count towards. What it reads is
//! `crate::readout::glare_grid`.

use super::check::{Context, line, number, unique_names};
use super::error::SceneError;
use super::grid::{Grid, cell_centres, edges, point_counts};
use super::observer::{Observer, line_of_sight, named_grid, ugr_limit};
use glam::{DQuat, DVec3};
use serde::Deserialize;
use serde_spanned::Spanned;
use std::path::Path;

/// `[[glare_grid]]` as written.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawGlareGrid {
    pub name: String,
    #[serde(deserialize_with = "super::arrays::exact")]
    pub origin: [f64; 3],
    #[serde(deserialize_with = "super::arrays::exact")]
    pub edge_u: [f64; 3],
    #[serde(deserialize_with = "super::arrays::exact")]
    pub edge_v: [f64; 3],
    #[serde(deserialize_with = "super::arrays::exact")]
    pub resolution: [i64; 2],
    #[serde(deserialize_with = "super::arrays::exact")]
    pub look: [f64; 3],
    pub view_step_deg: Option<Spanned<f64>>,
    pub ugr_limit: Option<f64>,
    pub grid: Option<Spanned<String>>,
}

/// The most eye positions along each edge of a glare grid.
const MOST_POSITIONS: usize = 100;

/// One line of sight of a glare grid: `look` turned by `turn_deg` about the vertical.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct View {
    /// The turn from the grid's `look`, degrees, from `+x` towards `−z` (right-handed about `+y`).
    pub turn_deg: f64,
    /// The unit line of sight.
    pub look: DVec3,
}

/// `[[glare_grid]]`: eyes at the centres of the `resolution = [nu, nv]` cells of the
/// parallelogram `origin + s·edge_u + t·edge_v` (the eye height is the height of its
/// points), each looking along every view.
#[derive(Debug, Clone, PartialEq)]
pub struct GlareGrid {
    /// The glare grid's name, unique among glare grids.
    pub name: String,
    /// The corner of the parallelogram, m.
    pub origin: DVec3,
    /// The first edge from `origin`, m.
    pub edge_u: DVec3,
    /// The second edge from `origin`, m.
    pub edge_v: DVec3,
    /// Eye positions along `edge_u` and `edge_v`, `[nu, nv]`.
    pub resolution: [usize; 2],
    /// The lines of sight, the first the table's `look`, every one at every position.
    pub views: Vec<View>,
    /// The UGR every reading is checked against (EN 12464-1's `UGR_L`), if given.
    pub ugr_limit: Option<f64>,
    /// The `[[grid]]` whose UGR every reading counts towards (`crate::readout::grid_ugr`), if given.
    pub grid: Option<String>,
}

impl GlareGrid {
    /// The eye positions, row by row along `edge_u`, rows stepping along `edge_v`.
    pub fn positions(&self) -> Vec<DVec3> {
        cell_centres(self.origin, [self.edge_u, self.edge_v], self.resolution)
    }

    /// One observer per position and view, position after position (`i·views + j`).
    pub fn observers(&self) -> Vec<Observer> {
        let [nu, _] = self.resolution;
        let one = |(i, position): (usize, DVec3)| {
            self.views.iter().map(move |view| Observer {
                name: format!("{} ({}, {}) {}°", self.name, i % nu, i / nu, view.turn_deg),
                position,
                look: view.look,
                ugr_limit: self.ugr_limit,
                grid: self.grid.clone(),
            })
        };
        self.positions().into_iter().enumerate().flat_map(one).collect()
    }
}

/// The glare grids, each checked key by key, each naming an existing grid if any.
pub(super) fn glare_grids(
    path: &Path,
    source: &str,
    raw: &[RawGlareGrid],
    grids: &[Grid],
) -> Result<Vec<GlareGrid>, SceneError> {
    unique_names(path, "glare_grid", raw.iter().map(|g| g.name.as_str()))?;
    raw.iter()
        .enumerate()
        .map(|(index, g)| glare_grid(&Context::item(path, "glare_grid", &g.name, index), source, g, grids))
        .collect()
}

fn glare_grid(at: &Context, source: &str, g: &RawGlareGrid, grids: &[Grid]) -> Result<GlareGrid, SceneError> {
    let origin = at.place("origin", g.origin)?;
    let [edge_u, edge_v] = edges(at, [g.edge_u, g.edge_v])?;
    let resolution = point_counts(at, g.resolution, MOST_POSITIONS)?;
    let look = line_of_sight(at, g.look)?;
    let step = g.view_step_deg.as_ref().map(|s| view_step(at, source, s)).transpose()?;
    let views = match step {
        None => vec![View { turn_deg: 0.0, look }],
        Some(step) => (0..(360.0 / step).round() as usize)
            .map(|k| k as f64 * step)
            .map(|turn_deg| View { turn_deg, look: DQuat::from_rotation_y(turn_deg.to_radians()) * look })
            .collect(),
    };
    let ugr_limit = ugr_limit(at, g.ugr_limit)?;
    let grid = named_grid(at, source, g.grid.as_ref(), grids)?;
    Ok(GlareGrid { name: g.name.clone(), origin, edge_u, edge_v, resolution, views, ugr_limit, grid })
}

/// `view_step_deg`: a whole fraction of the full turn, 360°/n for n from 1 to 360.
fn view_step(at: &Context, source: &str, step: &Spanned<f64>) -> Result<f64, SceneError> {
    let value = at.finite("view_step_deg", *step.get_ref())?;
    let n = 360.0 / value;
    if !(value > 0.0 && value <= 360.0 && (n - n.round()).abs() < 1e-9) || n.round() > 360.0 {
        let message = format!(
            "{}must divide the full turn into 1 to 360 equal steps (360, 90, 45, 30, 15, …), got {}",
            line(source, step),
            number(value)
        );
        return Err(at.error("view_step_deg", message));
    }
    Ok(value)
}
