//! The UGR lines of `ugo solve`'s summary (`docs/photometry.md`, "UGR"): per observer the
//! UGR, the background luminance, the luminaires counted, the check against its
//! `ugr_limit`, and a warning on stderr for sources outside the formula's solid angles;
//! per grid named by an observer its UGR (the largest of theirs) against its `UGR_L`.

use ugo::readout::grid::GridReading;
use ugo::readout::ugr::{UgrReading, VALID_SOLID_ANGLE, grid_ugr};

/// Whether `ugr` meets `limit`, in words.
pub(super) fn against(ugr: f64, limit: Option<f64>) -> String {
    match limit {
        Some(l) if ugr <= l => format!("≤ {l}: met"),
        Some(l) => format!("> {l}: NOT MET"),
        None => "-".to_string(),
    }
}

/// Warns on stderr that at `subject`, `what` a solid angle where CIE 117's formula does not hold.
pub(super) fn warn_outside(subject: &str, what: &str) {
    let [low, high] = VALID_SOLID_ANGLE;
    eprintln!(
        "ugo: warning: {subject}: {what} a solid angle outside {low}–{high} sr, where CIE 117's UGR does not hold"
    );
}

/// A UGR as printed.
pub(super) fn shown(ugr: f64) -> String {
    if ugr.is_finite() { format!("{ugr:.2}") } else { "no source".to_string() }
}

/// Prints one line per observer, then per grid its observers name, indented by `indent`.
pub fn report(readings: &[UgrReading], grids: &[GridReading], indent: &str) {
    println!("{indent}observers                       UGR   L_b cd/m²   sources   limit");
    for r in readings {
        let limit = against(r.ugr(), r.observer.ugr_limit);
        let o = &r.observer;
        println!(
            "{indent}  {:<22} {:>9} {:>11.4} {:>9}   {limit}",
            o.name,
            shown(r.ugr()),
            r.background,
            r.sources.len()
        );
        let outside = r.outside_validity();
        if outside > 0 {
            let what = format!("{outside} of its {} luminaires subtend", r.sources.len());
            warn_outside(&format!("observer \"{}\"", o.name), &what);
        }
    }
    grid_lines(readings, grids, indent);
}

/// One line per grid that an observer names: its UGR, the observers it is the largest of,
/// and its `UGR_L`.
fn grid_lines(readings: &[UgrReading], grids: &[GridReading], indent: &str) {
    let named: Vec<(&GridReading, f64)> =
        grids.iter().filter_map(|g| Some((g, grid_ugr(&g.grid.name, readings)?))).collect();
    if named.is_empty() {
        return;
    }
    println!("{indent}grids' UGR (largest of their observers)   observers   UGR_L");
    for (g, ugr) in named {
        let observers = readings.iter().filter(|r| r.observer.grid.as_deref() == Some(g.grid.name.as_str())).count();
        let limit = against(ugr, g.grid.target.ugr);
        println!("{indent}  {:<22} {:>9} {:>27}   {limit}", g.grid.name, shown(ugr), observers);
    }
}
