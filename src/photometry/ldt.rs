//! EULUMDAT photometric files (`.ldt`): one value per line, a decimal comma allowed.
//!
//! Layout: 1 company; 2 `Ityp` (0–3); 3 `Isym` (0–4); 4 `Mc`, the number of C-planes;
//! 5 `Dc`; 6 `Ng`, the number of γ angles; 7 `Dg`; 8–12 report, luminaire name and number,
//! file name, date; 13–21 dimensions (mm; 16–21 the luminous area, `super::luminous`); 22 downward flux fraction (%); 23 light output
//! ratio `LORL` (%); 24 conversion factor for intensities; 25 tilt during measurement;
//! 26 the number `n` of lamp sets, then six lines per set (number of lamps, type,
//! **total flux**, colour, colour rendering, watts); ten direct ratios; `Mc` C-angles; `Ng`
//! γ-angles; then the intensities in cd per 1000 lm of lamp flux, plane by plane, for the
//! planes the symmetry indicator stores:
//!
//! | `Isym` | symmetry | planes stored |
//! |---|---|---|
//! | 0 | none | all `Mc` |
//! | 1 | about the vertical axis | 1 |
//! | 2 | about the C0–C180 plane | C0…C180, `Mc/2 + 1` |
//! | 3 | about the C90–C270 plane | C90…C270, `Mc/2 + 1` |
//! | 4 | about both planes | C0…C90, `Mc/4 + 1` |
//!
//! Candela = value × lamp flux / 1000 × conversion factor, the lamp flux being the sum of
//! the lamp sets' total flux; the luminaire flux the file states is `LORL` × lamp flux.
//! C and γ are type C angles (γ = 0 at the nadir).

use super::error::PhotometryError;
use super::luminous::LuminousOpening;
use super::symmetry::{PLANE_C0, PLANE_C90, full_turn};
use super::system::System;
use super::table::{IntensityDistribution, check_intensity};
use std::ops::RangeInclusive;
use std::path::Path;

/// Reads an EULUMDAT file from the text of `file`.
pub fn parse(file: &Path, text: &str) -> Result<IntensityDistribution, PhotometryError> {
    let mut r = Lines { file, lines: text.lines().collect(), next: 0 };
    r.text("the company line")?;
    r.integer("the type indicator Ityp", 0..=3)?;
    let isym = r.integer("the symmetry indicator Isym", 0..=4)?;
    let isym_line = r.line();
    let mc = r.integer("the number of C-planes Mc", 1..=3600)? as usize;
    r.number("the C-plane spacing Dc")?;
    let ng = r.integer("the number of γ angles Ng", 2..=1801)? as usize;
    r.number("the γ spacing Dg")?;
    for what in ["the report number", "the luminaire name", "the luminaire number", "the file name", "the date"] {
        r.text(what)?;
    }
    for what in ["the luminaire length", "its width", "its height"] {
        r.number(what)?;
    }
    let length = r.number("the luminous area's length")? / 1000.0;
    let width = r.number("the luminous area's width")? / 1000.0;
    let mut height = 0.0;
    for plane in ["C0", "C90", "C180", "C270"] {
        height += r.number(&format!("the luminous area's height at {plane}"))? / 4000.0;
    }
    r.number("the downward flux fraction")?;
    let lorl = r.number("the light output ratio LORL (%)")?;
    if !(0.0..=100.0).contains(&lorl) {
        return Err(r.error(format!("expected the light output ratio LORL (0 to 100 %), got {lorl}")));
    }
    let conversion = r.number("the conversion factor for intensities")?;
    let conversion_line = r.line();
    if conversion <= 0.0 {
        return Err(
            r.error(format!("expected the conversion factor for intensities (greater than 0), got {conversion}"))
        );
    }
    r.number("the tilt during measurement")?;
    let sets = r.integer("the number of lamp sets", 1..=20)?;
    let mut lamp_flux = 0.0;
    for set in 1..=sets {
        r.integer(&format!("the number of lamps of set {set}"), -10_000..=10_000)?;
        r.text(&format!("the lamp type of set {set}"))?;
        let flux = r.number(&format!("the total flux of lamp set {set} (lm)"))?;
        if flux <= 0.0 {
            return Err(r.error(format!("expected the total flux of lamp set {set} (greater than 0 lm), got {flux}")));
        }
        lamp_flux += flux;
        r.text(&format!("the colour appearance of set {set}"))?;
        r.text(&format!("the colour rendering of set {set}"))?;
        r.number(&format!("the wattage of set {set}"))?;
    }
    for k in 1..=10 {
        r.number(&format!("direct ratio {k} of 10"))?;
    }
    let first_c = r.line() + 1;
    let c = r.angles(mc, "C", 0.0, 360.0 - 1e-9)?;
    let last_c = r.line();
    let gamma = r.angles(ng, "γ", 0.0, 180.0)?;

    let (span, mirrors, name): ((f64, f64), &[f64], &str) = match isym {
        0 => ((0.0, 360.0), &[], "no symmetry"),
        1 => ((0.0, 360.0), &[], "symmetry about the vertical axis"),
        2 => ((0.0, 180.0), &[PLANE_C0], "symmetry about the C0–C180 plane"),
        3 => ((90.0, 270.0), &[PLANE_C90], "symmetry about the C90–C270 plane"),
        _ => ((0.0, 90.0), &[PLANE_C0, PLANE_C90], "symmetry about the C0–C180 and C90–C270 planes"),
    };
    let stored: Vec<f64> = match isym {
        1 => vec![0.0],
        _ => c.iter().copied().filter(|a| (span.0..=span.1).contains(a)).collect(),
    };
    let expected = match isym {
        0 => mc,
        1 => 1,
        2 | 3 => mc / 2 + 1,
        _ => mc / 4 + 1,
    };
    let ends = stored.first().zip(stored.last()).is_some_and(|(&a, &b)| isym <= 1 || (a == span.0 && b == span.1));
    if stored.len() != expected || !ends {
        let message = format!(
            "with Isym {isym} (line {isym_line}) the file stores {expected} C-planes from C{}° to C{}°, but the \
             C-angles on lines {first_c}–{last_c} hold {} there{}",
            span.0,
            if isym <= 1 { 360.0 - 360.0 / mc as f64 } else { span.1 },
            stored.len(),
            if ends { "" } else { " (the end planes are missing)" }
        );
        return Err(PhotometryError::at(file, first_c, message));
    }
    let mut columns = Vec::with_capacity(stored.len());
    for &plane in &stored {
        let mut column = Vec::with_capacity(ng);
        for j in 0..ng {
            let what = format!("intensity {} of {ng} in plane C{plane}° (cd/klm)", j + 1);
            let value = r.number(&what)?;
            check_intensity(value, &what).map_err(|m| r.error(m))?;
            column.push(value);
        }
        columns.push((plane, column));
    }
    if let Some(extra) = r.lines[r.next..].iter().position(|l| !l.trim().is_empty()) {
        let line = r.next + extra + 1;
        let message = format!(
            "unexpected '{}' after the {} × {ng} intensities: Mc, Ng or Isym do not match the data",
            r.lines[line - 1].trim(),
            stored.len()
        );
        return Err(PhotometryError::at(file, line, message));
    }
    let mut table = IntensityDistribution::new(System::C, full_turn(columns, mirrors), gamma, true);
    table.scale(lamp_flux / 1000.0 * conversion);
    if !table.is_finite() {
        let message = format!(
            "the intensities times the lamp flux {lamp_flux:e} lm / 1000 and the conversion factor {conversion:e} \
             overflow double precision"
        );
        return Err(PhotometryError::at(file, conversion_line, message));
    }
    table.stated_flux = Some(lorl / 100.0 * lamp_flux);
    table.lamp_flux = Some(lamp_flux);
    table.luminous = LuminousOpening::of_ldt(length, width, height);
    table.description = format!("EULUMDAT, Isym {isym}: {name}");
    Ok(table)
}

/// The lines of the file, read one value at a time.
struct Lines<'a> {
    file: &'a Path,
    lines: Vec<&'a str>,
    next: usize,
}

impl<'a> Lines<'a> {
    /// The 1-based line read last.
    fn line(&self) -> usize {
        self.next.max(1)
    }

    fn error(&self, message: impl Into<String>) -> PhotometryError {
        PhotometryError::at(self.file, self.line(), message)
    }

    fn text(&mut self, what: &str) -> Result<&'a str, PhotometryError> {
        let Some(&line) = self.lines.get(self.next) else {
            let at = self.lines.len().max(1);
            return Err(PhotometryError::at(self.file, at, format!("expected {what}, found the end of the file")));
        };
        self.next += 1;
        Ok(line.trim())
    }

    /// A line holding one finite number (a decimal comma is read as a point).
    fn number(&mut self, what: &str) -> Result<f64, PhotometryError> {
        let text = self.text(what)?;
        match text.replace(',', ".").parse::<f64>() {
            Ok(x) if x.is_finite() => Ok(x),
            _ => Err(self.error(format!("expected {what} (one number), got '{text}'"))),
        }
    }

    fn integer(&mut self, what: &str, range: RangeInclusive<i64>) -> Result<i64, PhotometryError> {
        let x = self.number(what)?;
        let n = x as i64;
        if x.fract() != 0.0 || !range.contains(&n) {
            let message = format!("expected {what} (an integer from {} to {}), got {x}", range.start(), range.end());
            return Err(self.error(message));
        }
        Ok(n)
    }

    /// `n` strictly increasing angles within `[low, high]`, one per line.
    fn angles(&mut self, n: usize, what: &str, low: f64, high: f64) -> Result<Vec<f64>, PhotometryError> {
        let mut out: Vec<f64> = Vec::with_capacity(n);
        for i in 0..n {
            let a = self.number(&format!("{what}-angle {} of {n}", i + 1))?;
            if a < low || a > high {
                let message = format!("expected {what}-angle {} of {n} within {low}…{}°, got {a}", i + 1, high.round());
                return Err(self.error(message));
            }
            if let Some(&before) = out.last()
                && a <= before
            {
                let message =
                    format!("{what}-angles must increase: {what}-angle {} of {n} is {a}°, after {before}°", i + 1);
                return Err(self.error(message));
            }
            out.push(a);
        }
        Ok(out)
    }
}
