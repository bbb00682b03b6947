//! The report's glare table (`docs/report.md`): the UGR of CIE 117 at every `[[observer]]`
//! (`/observers`) against its `UGR_L` of EN 12464-1 where the case gives one, with the
//! background luminance it was read with.

use super::super::read::Result;
use super::h5::H5;
use super::html::{escape, number, section, table, verdict};

/// A UGR as shown: one decimal, or "no source" where no luminaire is counted.
pub(super) fn ugr(value: f64) -> String {
    if value.is_finite() { format!("{value:.1}") } else { "no source".to_string() }
}

/// A UGR as shown against its limit `limit` (`UGR_L`): coloured as met or not where the
/// limit is finite, plain otherwise.
pub(super) fn ugr_against(value: f64, limit: f64) -> String {
    if !limit.is_finite() {
        return ugr(value);
    }
    let class = if !value.is_finite() || value <= limit { "pass" } else { "fail" };
    format!("<span class=\"{class}\">{}</span>", ugr(value))
}

/// The observers' table, or nothing for a case without observers.
pub(super) fn observers(h: &H5) -> Result<Option<String>> {
    if !h.has("observers/name") {
        return Ok(None);
    }
    let names = h.strings("observers/name")?;
    if names.is_empty() {
        return Ok(None);
    }
    let n = names.len();
    let (values, limits) = (h.numbers_of("observers/ugr", n)?, h.numbers_of("observers/ugr_limit", n)?);
    let background = h.numbers_of("observers/background_luminance", n)?;
    let rows: Vec<Vec<String>> = (0..n)
        .map(|i| {
            let met = limits[i].is_finite().then(|| !values[i].is_finite() || values[i] <= limits[i]);
            vec![escape(&names[i]), ugr(values[i]), number(limits[i], 0), verdict(met), number(background[i], 1)]
        })
        .collect();
    let head = ["observer", "UGR", "UGR_L", "within UGR_L", "background luminance (cd/m²)"].map(str::to_string);
    let body = table("observers", &head, &rows);
    Ok(Some(section("glare", "Glare (UGR, CIE 117)", &body)))
}
