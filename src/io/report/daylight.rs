//! The report's daylight (`docs/report.md`): under a `[sky]`, every grid's daylight factor
//! (or ratio) `DF_avg`, `DF_min`, `DF_max` and uniformity `DF_min / DF_avg` from
//! `/daylight/grids/<name>`, its plan drawn from the stored values, and the sky component,
//! externally and internally reflected components and daylight factor at every probe
//! (`/daylight/probes`), all in %.

use super::super::grid_map::Shown;
use super::super::read::Result;
use super::grids::{plan, reading, sources};
use super::h5::H5;
use super::html::{escape, image, number, paragraph, section, table};
use crate::io::StoredSolution;

/// The daylight section, or nothing for a file without `/daylight`.
pub(super) fn daylight(h: &H5, stored: &StoredSolution) -> Result<Option<String>> {
    if !h.has("daylight") {
        return Ok(None);
    }
    let e_h = h.attr("daylight", "E_h").unwrap_or(f64::NAN);
    let ratio = h.0.h5.group("daylight")?.attr("quantity")?.read_scalar::<hdf5::types::VarLenUnicode>()?;
    let symbol = if ratio.as_str() == "daylight ratio" { "DR" } else { "DF" };
    let mut body = paragraph(&format!(
        "{} (%): the share of the unobstructed sky's horizontal illuminance E_h = {} lx.",
        ratio.as_str(),
        number(e_h, 0)
    ));
    let stats = ["avg", "min", "max"].map(|s| format!("{symbol}_{s} (%)"));
    let head: Vec<String> = ["grid".to_string()].into_iter().chain(stats).chain(["uniformity".to_string()]).collect();
    let mut rows = Vec::new();
    let mut plans = String::new();
    let sources = sources(stored);
    for grid in &stored.scene.grids {
        let at = format!("daylight/grids/{}", grid.name);
        let [avg, min, max, u] = h.attrs(&at, ["DF_avg", "DF_min", "DF_max", "uniformity"]);
        rows.push(vec![escape(&grid.name), number(avg, 2), number(min, 2), number(max, 2), number(u, 2)]);
        let r = reading(h, &format!("grids/{}", grid.name), grid)?;
        let values = h.numbers_of(&format!("{at}/daylight_factor"), r.points.len())?;
        let png = plan(stored, &r, &Shown::daylight(&values, symbol), &sources)?;
        plans += &image(&png, &format!("plan of the grid {}: {}, %", grid.name, ratio.as_str()));
    }
    if !rows.is_empty() {
        body += &table("daylight-grids", &head, &rows);
        body += &plans;
    }
    let names = h.strings("daylight/probes/name")?;
    if !names.is_empty() {
        let n = names.len();
        let parts = ["sky_component", "externally_reflected", "internally_reflected", "daylight_factor"];
        let columns = parts.map(|p| h.numbers_of(&format!("daylight/probes/{p}"), n));
        let columns = columns.into_iter().collect::<Result<Vec<_>>>()?;
        let rows: Vec<Vec<String>> = (0..n)
            .map(|i| std::iter::once(escape(&names[i])).chain(columns.iter().map(|c| number(c[i], 2))).collect())
            .collect();
        let head = ["probe", "SC (%)", "ERC (%)", "IRC (%)", &format!("{symbol} (%)")].map(str::to_string);
        body += &table("daylight-probes", &head, &rows);
    }
    Ok(Some(section("daylight", "Daylight", &body)))
}
