//! The UGR lines of `ugo solve`'s summary (`docs/photometry.md`, "UGR"): per observer the
//! UGR, the background luminance, the luminaires counted, the check against its
//! `ugr_limit`, and a warning on stderr for sources outside the formula's solid angles.

use ugo::readout::ugr::{UgrReading, VALID_SOLID_ANGLE};

/// Prints one line per observer, the table indented by `indent`.
pub fn report(readings: &[UgrReading], indent: &str) {
    println!("{indent}observers                       UGR   L_b cd/m²   sources   limit");
    for r in readings {
        let limit = match r.observer.ugr_limit {
            Some(l) if r.sources.is_empty() || r.ugr() <= l => format!("≤ {l}: met"),
            Some(l) => format!("> {l}: NOT MET"),
            None => "-".to_string(),
        };
        let o = &r.observer;
        let ugr = if r.sources.is_empty() { "no source".to_string() } else { format!("{:.2}", r.ugr()) };
        println!("{indent}  {:<22} {ugr:>9} {:>11.4} {:>9}   {limit}", o.name, r.background, r.sources.len());
        let outside = r.outside_validity();
        if outside > 0 {
            let [low, high] = VALID_SOLID_ANGLE;
            eprintln!(
                "ugo: warning: observer \"{}\": {outside} of its {} luminaires subtend a solid angle outside {low}–{high} sr, where CIE 117's UGR does not hold",
                o.name,
                r.sources.len()
            );
        }
    }
}
