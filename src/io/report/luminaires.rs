//! The report's luminaire table (`docs/report.md`): the electric luminaires of
//! `/luminaires` (openings left to the daylight), consecutive ones of the same kind,
//! file, group and maintained flux in one row with their count (an array's members), the
//! flux in lm before and after the maintenance factor of `[lighting]`.

use super::super::read::Result;
use super::h5::H5;
use super::html::{escape, number, section, table};

/// One row: the luminaires from `first` to `last` alike.
struct Row {
    first: String,
    last: String,
    kind: String,
    file: String,
    group: String,
    flux: f64,
    count: usize,
}

impl Row {
    fn takes(&self, kind: &str, file: &str, group: &str, flux: f64) -> bool {
        self.kind == kind && self.file == file && self.group == group && (self.flux - flux).abs() <= 1e-9 * flux.abs()
    }
}

/// The luminaire table, or nothing for a file without electric luminaires.
pub(super) fn luminaires(h: &H5) -> Result<Option<String>> {
    if !h.has("luminaires/group") {
        return Ok(None);
    }
    let names = h.strings("luminaires/name")?;
    let n = names.len();
    let (kinds, files, groups) =
        (h.strings("luminaires/kind")?, h.strings("luminaires/file")?, h.strings("luminaires/group")?);
    let flux = h.numbers_of("luminaires/flux", n)?;
    if kinds.len() != n || files.len() != n || groups.len() != n {
        return Err(super::super::read::Why("the datasets of /luminaires disagree on the number of luminaires".into()));
    }
    let mut rows: Vec<Row> = Vec::new();
    for i in (0..n).filter(|&i| kinds[i] != "window") {
        match rows.last_mut() {
            Some(row) if row.takes(&kinds[i], &files[i], &groups[i], flux[i]) => {
                row.count += 1;
                row.last.clone_from(&names[i]);
            }
            _ => rows.push(Row {
                first: names[i].clone(),
                last: names[i].clone(),
                kind: kinds[i].clone(),
                file: files[i].clone(),
                group: groups[i].clone(),
                flux: flux[i],
                count: 1,
            }),
        }
    }
    if rows.is_empty() {
        return Ok(None);
    }
    let mf = h.attr("luminaires", "maintenance_factor").unwrap_or(1.0);
    let head = [
        "luminaire",
        "kind",
        "file",
        "count",
        "flux each (lm)",
        "maintenance factor",
        "maintained flux each (lm)",
        "maintained flux, all (lm)",
        "group",
    ];
    let cells = |r: &Row| {
        let name =
            if r.count == 1 { escape(&r.first) } else { format!("{} … {}", escape(&r.first), escape(&r.last)) };
        let file = if r.file.is_empty() { "—".to_string() } else { escape(&r.file) };
        vec![
            name,
            escape(&r.kind),
            file,
            r.count.to_string(),
            number(r.flux / mf, 1),
            number(mf, 2),
            number(r.flux, 1),
            number(r.flux * r.count as f64, 1),
            escape(&r.group),
        ]
    };
    let head: Vec<String> = head.map(str::to_string).to_vec();
    let body = table("luminaires", &head, &rows.iter().map(cells).collect::<Vec<_>>());
    Ok(Some(section("luminaires", "Luminaires", &body)))
}
