//! The report's page (`docs/report.md`): the head with its style, the case and its solve,
//! then every section the file has the figures for, in a lighting engineer's order:
//! materials, luminaires, grids and plans, glare, glare grids, light scenes, daylight, surfaces, probes,
//! warnings.

use super::super::read::Result;
use super::h5::H5;
use super::html::{escape, number, paragraph, section, table};
use crate::io::StoredSolution;

const STYLE: &str = "body{font-family:sans-serif;margin:2em;max-width:1100px;color:#222}\
h1{font-size:1.6em}h2{font-size:1.25em;border-bottom:1px solid #aaa;margin-top:1.6em}\
table{border-collapse:collapse;margin:0.6em 0}th,td{border:1px solid #bbb;padding:3px 8px;text-align:right}\
th{background:#eee}td:first-child,th:first-child{text-align:left}\
.pass{color:#176f2c;font-weight:bold}.fail{color:#b01c1c;font-weight:bold}\
figure{margin:0.8em 0}img{max-width:100%}li{margin:0.3em 0}";

/// The whole page of the solution `h` (stored as `stored`), named `file`.
pub(super) fn page(h: &H5, stored: &StoredSolution, file: &str) -> Result<String> {
    let scene = &stored.scene;
    let title = format!("ugo report: {}", scene.name);
    let mut body = format!("<h1>{}</h1>\n", escape(&title));
    if !scene.description.is_empty() {
        body += &paragraph(&scene.description);
    }
    body += &solve(h, stored, file);
    body += &super::surfaces::materials(stored);
    let sections = [
        super::luminaires::luminaires(h)?,
        super::grids::grids(h, stored)?,
        super::glare::observers(h)?,
        super::glare_grids::glare_grids(h, stored)?,
        super::light_scenes::light_scenes(h, stored)?,
        super::daylight::daylight(h, stored)?,
        Some(super::surfaces::surfaces(h, stored)?),
        super::probes::probes(h)?,
        warnings(h)?,
    ];
    body += &sections.into_iter().flatten().collect::<String>();
    Ok(format!(
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>{}</title>\n\
         <style>{STYLE}</style>\n</head>\n<body>\n{body}</body>\n</html>\n",
        escape(&title)
    ))
}

/// The case and how it was solved: the file, the room's extent, patches, kernel, method,
/// residual, flux and the times of assembly, the sources' direct light and solve.
fn solve(h: &H5, stored: &StoredSolution, file: &str) -> String {
    let (low, high) = stored
        .mesh
        .patches
        .iter()
        .flat_map(|p| p.polygon.vertices().to_vec())
        .fold((glam::DVec3::INFINITY, glam::DVec3::NEG_INFINITY), |(lo, hi), v| (lo.min(v), hi.max(v)));
    let size = high - low;
    let text = |name: &str| h.text(name).unwrap_or_else(|| "—".to_string());
    let [residual, emitted, absorbed] = h.attrs("", ["residual", "flux_emitted", "flux_absorbed"]);
    let [assembly, direct, solving] = h.attrs("", ["assembly_seconds", "luminaire_seconds", "solve_seconds"]);
    let rows = [
        ("solution file", escape(file)),
        ("case file", escape(&text("scene_file"))),
        ("extent x × y × z (m)", format!("{} × {} × {}", number(size.x, 2), number(size.y, 2), number(size.z, 2))),
        ("patches", stored.mesh.len().to_string()),
        ("direction cells", stored.directions.len().to_string()),
        ("kernel, method", escape(&format!("{}, {}", text("kernel"), text("method")))),
        ("relative residual", format!("{residual:.1e}")),
        ("flux emitted, absorbed (lm)", format!("{}, {}", number(emitted, 1), number(absorbed, 1))),
        ("assembly, sources' direct light, solve (s)", [assembly, direct, solving].map(|t| number(t, 1)).join(", ")),
        ("ugo version", escape(&text("version"))),
    ];
    let rows: Vec<Vec<String>> = rows.into_iter().map(|(k, v)| vec![k.to_string(), v]).collect();
    section("case", "Case and solve", &table("case", &["quantity".to_string(), "value".to_string()], &rows))
}

/// The warnings the solve stored, or nothing when there are none.
fn warnings(h: &H5) -> Result<Option<String>> {
    let warnings = if h.has("warnings") { h.strings("warnings")? } else { Vec::new() };
    if warnings.is_empty() {
        return Ok(None);
    }
    let items: String = warnings.iter().map(|w| format!("<li>{}</li>\n", escape(w))).collect();
    Ok(Some(section("warnings", "Warnings", &format!("<ul>\n{items}</ul>\n"))))
}
