//! The report's glare grids (`docs/report.md`, `docs/photometry.md` "UGR on a grid of
//! observers"): per `[[glare_grid]]` of the stored case (`/glare_grids/<name>`) its
//! positions and views, eye height, the largest UGR and where against its `UGR_L`, the
//! positions above it, and the `[[grid]]` whose UGR it counts towards (`grid`); then for
//! each the largest UGR over the views at every eye position, a table laid out as the
//! positions (a row per step along `edge_v`, a column per step along `edge_u`).

use super::super::read::Result;
use super::glare::ugr;
use super::h5::H5;
use super::html::{escape, number, optional, paragraph, section, table, verdict};
use crate::io::StoredSolution;
use crate::scene::GlareGrid;

/// The glare grids' section, or nothing for a case without glare grids.
pub(super) fn glare_grids(h: &H5, stored: &StoredSolution) -> Result<Option<String>> {
    let path = |g: &GlareGrid| format!("glare_grids/{}/ugr", g.name);
    let grids: Vec<&GlareGrid> = stored.scene.glare_grids.iter().filter(|g| h.has(&path(g))).collect();
    if grids.is_empty() {
        return Ok(None);
    }
    let (mut rows, mut maps) = (Vec::new(), String::new());
    for (k, g) in grids.into_iter().enumerate() {
        let [nu, nv] = g.resolution;
        let values = h.numbers_of(&path(g), nu * nv * g.views.len())?;
        let per_position: Vec<f64> =
            values.chunks(g.views.len()).map(|c| c.iter().copied().fold(f64::NEG_INFINITY, f64::max)).collect();
        rows.push(summary_row(g, &values, &per_position));
        maps += &paragraph(&format!(
            "{}: the largest UGR over the views at each eye position (u along edge_u, v along edge_v).",
            g.name
        ));
        maps += &positions_table(&format!("glare-grid-{}", k + 1), nu, &per_position);
    }
    let head = [
        "glare grid",
        "positions × views",
        "eye height (m)",
        "views",
        "UGR_max",
        "at (u, v, turn)",
        "UGR_L",
        "within UGR_L",
        "positions above UGR_L",
        "UGR of grid",
    ]
    .map(str::to_string);
    let body = table("glare-grids", &head, &rows) + &maps;
    Ok(Some(section("glare-grids", "Glare on grids of observers (UGR, CIE 117)", &body)))
}

/// A glare grid's row: its size, eye height, views, largest UGR and where, and the check.
fn summary_row(g: &GlareGrid, values: &[f64], per_position: &[f64]) -> Vec<String> {
    let ([nu, nv], views) = (g.resolution, g.views.len());
    let first = (0..values.len()).fold(0, |best, k| if values[k] > values[best] { k } else { best });
    let largest = values[first];
    let (position, turn) = (first / views, g.views[first % views].turn_deg);
    let heights = g
        .positions()
        .iter()
        .map(|p| p.y)
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), y| (lo.min(y), hi.max(y)));
    let height = match heights {
        (lo, hi) if hi - lo < 5e-3 => number(lo, 2),
        (lo, hi) => format!("{}–{}", number(lo, 2), number(hi, 2)),
    };
    let turns = match views {
        1 => "one".to_string(),
        n => format!("{n}, every {}°", g.views[1].turn_deg),
    };
    let met = g.ugr_limit.map(|l| largest <= l);
    let above = g
        .ugr_limit
        .map_or("—".to_string(), |l| format!("{} of {}", per_position.iter().filter(|&&u| u > l).count(), nu * nv));
    vec![
        escape(&g.name),
        format!("{nu} × {nv} × {views}"),
        height,
        turns,
        ugr(largest),
        format!("({}, {}, {turn}°)", position % nu, position / nu),
        optional(g.ugr_limit, 0),
        verdict(met),
        above,
        g.grid.as_deref().map_or("—".to_string(), escape),
    ]
}

/// The largest UGR at each position, a row per `v`, a column per `u`.
fn positions_table(id: &str, nu: usize, per_position: &[f64]) -> String {
    let head: Vec<String> = std::iter::once("v \\ u".to_string()).chain((0..nu).map(|u| u.to_string())).collect();
    let rows: Vec<Vec<String>> = per_position
        .chunks(nu)
        .enumerate()
        .map(|(v, row)| std::iter::once(v.to_string()).chain(row.iter().map(|&u| ugr(u))).collect())
        .collect();
    table(id, &head, &rows)
}
