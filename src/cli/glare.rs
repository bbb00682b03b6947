//! The UGR lines of `ugo solve`'s summary (`docs/photometry.md`, "UGR"): per observer the
//! UGR, the background luminance, the luminaires counted, the check against its
//! `ugr_limit`, and a warning on stderr for sources outside the formula's solid angles;
//! per grid named by an observer or a glare grid its UGR (the largest of their readings,
//! `ugo::readout::grid_ugr`) against its `UGR_L`.

use ugo::readout::grid::GridReading;
use ugo::readout::grid_ugr::{GlareReadings, GridUgr};
use ugo::readout::ugr::{UgrReading, VALID_SOLID_ANGLE};

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

/// Prints one line per observer (when there are any), then per grid its observers and glare
/// grids name, indented by `indent`.
pub fn report(glare: GlareReadings, grids: &[GridReading], indent: &str) {
    if !glare.observers.is_empty() {
        observer_lines(glare.observers, indent);
    }
    grid_lines(glare, grids, indent);
}

fn observer_lines(readings: &[UgrReading], indent: &str) {
    say!("{indent}observers                       UGR   L_b cd/m²   sources   limit");
    for r in readings {
        let limit = against(r.ugr(), r.observer.ugr_limit);
        let o = &r.observer;
        say!("{indent}  {:<22} {:>9} {:>11.4} {:>9}   {limit}", o.name, shown(r.ugr()), r.background, r.sources.len());
        let outside = r.outside_validity();
        if outside > 0 {
            let what = format!("{outside} of its {} luminaires subtend", r.sources.len());
            warn_outside(&format!("observer \"{}\"", o.name), &what);
        }
    }
}

/// One line per grid that an observer or a glare grid names: its UGR (the largest of
/// theirs), what it is taken from, and its `UGR_L`.
fn grid_lines(glare: GlareReadings, grids: &[GridReading], indent: &str) {
    let named: Vec<(&GridReading, GridUgr)> =
        grids.iter().filter_map(|g| Some((g, glare.grid_ugr(&g.grid.name)?))).collect();
    if named.is_empty() {
        return;
    }
    say!("{indent}grids' UGR                     UGR   from (largest of their readings)   UGR_L");
    for (g, u) in named {
        let from = taken_from(&u);
        let limit = against(u.ugr, g.grid.target.ugr);
        say!("{indent}  {:<22} {:>9}   {from:<32}   {limit}", g.grid.name, shown(u.ugr));
    }
}

/// What a grid's UGR is taken from, in words: "2 observers, glare grid \"desks\"".
fn taken_from(u: &GridUgr) -> String {
    let observers = match u.observers {
        0 => None,
        1 => Some("1 observer".to_string()),
        n => Some(format!("{n} observers")),
    };
    let grids = u.glare_grids.iter().map(|g| format!("glare grid \"{g}\""));
    observers.into_iter().chain(grids).collect::<Vec<_>>().join(", ")
}
