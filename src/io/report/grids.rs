//! The grids of the report (`docs/report.md`): each `[[grid]]` of the stored scene against
//! the targets of EN 12464-1 its case gives it (`Ēm`, `U0`, `UGR_L` against the largest UGR
//! of the `[[observer]]`s and `[[glare_grid]]`s that name it), from the statistics
//! `/grids/<name>` holds, and its plan drawn again from the stored readings by
//! `io::grid_map` (the same picture as `ugo solve`'s `OUT-<grid>.png`).

use super::super::grid_map::{Shown, plan_png};
use super::super::read::{Result, Why};
use super::h5::H5;
use super::html::{escape, image, number, optional, section, table, verdict, with_bar};
use crate::geometry::section as cut;
use crate::io::{Overlay, StoredSolution};
use crate::luminaire::Source;
use crate::readout::grid::GridReading;
use crate::readout::obstructed::Obstruction;
use crate::scene::Grid;

/// The statistics a grid's group holds, in the order of the table.
const STATS: [&str; 4] = ["E_avg", "E_min", "E_max", "U0"];

/// The header of a grid's figures against its targets.
pub(super) fn target_head() -> Vec<String> {
    ["E_avg (lx)", "Ēm target (lx)", "E_min (lx)", "E_max (lx)", "U0", "U0 target", "UGR", "UGR_L", "meets targets"]
        .map(str::to_string)
        .to_vec()
}

/// The cells of `head` for the grid `grid` whose statistics are the attributes of `group`
/// (`E_avg`, `E_min` and `U0` with their error bars where the group holds them; its UGR the
/// largest of the observers and glare grids that name it, "-" where none does).
pub(super) fn figures(h: &H5, group: &str, grid: &Grid) -> Vec<String> {
    let [avg, min, max, u0] = h.attrs(group, STATS);
    let t = grid.target;
    let ugr = h.attr(group, "UGR");
    let bar = |name: &str| h.attr(group, &format!("{name}_error"));
    let glare = t.ugr.map(|limit| ugr.is_some_and(|u| u <= limit));
    let checks: Vec<bool> =
        [t.em.map(|em| avg >= em), t.u0.map(|least| u0 >= least), glare].into_iter().flatten().collect();
    let met = (!checks.is_empty()).then(|| checks.iter().all(|&ok| ok));
    vec![
        with_bar(avg, bar("E_avg"), 1),
        optional(t.em, 0),
        with_bar(min, bar("E_min"), 1),
        number(max, 1),
        with_bar(u0, bar("U0"), 2),
        optional(t.u0, 2),
        ugr.map_or("-".to_string(), super::glare::ugr),
        optional(t.ugr, 0),
        verdict(met),
    ]
}

/// The grids' table and their plans, or nothing for a case without grids.
pub(super) fn grids(h: &H5, stored: &StoredSolution) -> Result<Option<String>> {
    let grids = &stored.scene.grids;
    if grids.is_empty() {
        return Ok(None);
    }
    let mut head = vec!["grid".to_string(), "points counted".to_string()];
    head.extend(target_head());
    let mut rows = Vec::new();
    let mut plans = String::new();
    let sources = sources(stored);
    for grid in grids {
        let reading = reading(h, &format!("grids/{}", grid.name), grid)?;
        let counted = reading.points.len() - reading.left_out();
        let mut row = vec![escape(&grid.name), format!("{counted} of {}", reading.points.len())];
        row.extend(figures(h, &format!("grids/{}", grid.name), grid));
        rows.push(row);
        let png = plan(stored, &reading, &Shown::illuminance(&reading), &sources)?;
        plans += &image(&png, &format!("plan of the grid {}: illuminance, lx", grid.name));
    }
    let body = table("grids", &head, &rows) + &plans;
    Ok(Some(section("grids", "Grids against EN 12464-1 (illuminance, lx)", &body)))
}

/// The grid `grid` as the solve read it, from the group `group` (`/grids/<name>` or a light
/// scene's): illuminance, its direct part and the points left out of the statistics.
pub(super) fn reading(h: &H5, group: &str, grid: &Grid) -> Result<GridReading> {
    let points = grid.points();
    let n = points.len();
    let illuminance = h.numbers_of(&format!("{group}/illuminance"), n)?;
    let direct = h.numbers_of(&format!("{group}/direct"), n)?;
    let surface = h.0.raw::<i64>(&format!("{group}/obstruction_surface"))?;
    let inside = h.0.raw::<u8>(&format!("{group}/obstruction_inside"))?;
    let distance = h.numbers_of(&format!("{group}/obstruction_distance"), n)?;
    if surface.len() != n || inside.len() != n {
        return Err(Why(format!("/{group}/obstruction_* do not hold one value per point ({n})")));
    }
    let surfaces = stored_surfaces(h)?;
    let obstructed = (0..n)
        .map(|i| match usize::try_from(surface[i]) {
            Ok(s) if s < surfaces => {
                Ok(Some(Obstruction { surface: s, inside: inside[i] != 0, distance: distance[i] }))
            }
            Ok(s) => Err(Why(format!("/{group}/obstruction_surface[{i}] = {s}, past the {surfaces} surfaces"))),
            Err(_) => Ok(None),
        })
        .collect::<Result<Vec<_>>>()?;
    Ok(GridReading { grid: grid.clone(), points, illuminance, direct, obstructed })
}

fn stored_surfaces(h: &H5) -> Result<usize> {
    Ok(h.strings("mesh/surface_names")?.len())
}

/// The stored scene's luminaires placed, each at full output.
pub(super) fn sources(stored: &StoredSolution) -> Vec<Source> {
    stored.scene.luminaires.iter().map(Source::of).collect()
}

/// The plan of `shown` on `reading` as PNG bytes, with `sources` (dimmed as a light scene
/// has them) and the section of the stored patches by the grid's plane.
pub(super) fn plan(
    stored: &StoredSolution,
    reading: &GridReading,
    shown: &Shown,
    sources: &[Source],
) -> Result<Vec<u8>> {
    let section = cut(&stored.mesh, reading.grid.origin, reading.grid.normal);
    let overlay = Overlay { sources, section: &section };
    plan_png(reading, shown, &overlay).map_err(|e| Why(format!("the plan of grid \"{}\": {e}", reading.grid.name)))
}
