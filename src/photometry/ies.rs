//! IES LM-63 photometric files (`.ies`): versions 1995, 2002 and 2019 (and `IESNA91`,
//! read as 1995), `TILT=NONE` and `TILT=INCLUDE`, photometric types A, B and C, relative
//! and absolute photometry (lumens per lamp = −1), values wrapping over any number of lines
//! (separated by blanks or commas).
//!
//! Layout (after the version line and the `[KEYWORD]` lines): `TILT=…`, the tilt record if
//! included (lamp-to-luminaire geometry, count, angles, factors), then the record
//! `lamps, lumens per lamp, candela multiplier, N_v, N_h, type, units, width, length,
//! height` (the luminous opening, `super::luminous`), then `ballast factor, (1995: ballast-lamp photometric factor; later: unused or
//! file-generation type), input watts`, the `N_v` vertical and `N_h` horizontal angles, and
//! `N_h` blocks of `N_v` candela values. Candela are multiplied by the candela multiplier and
//! the ballast factor (and, in 1995 files, the ballast-lamp photometric factor).
//!
//! Symmetries implied by the horizontal angles (LM-63-2002; 90–270 from LM-63-1995):
//! type C — one angle: axial; 0–90: quadrant; 0–180: bilateral about the C0–C180 plane;
//! 90–270: bilateral about the C90–C270 plane; 0 to more than 180 (up to 360): none.
//! Types A and B — 0–90: lateral (H → −H); −90–90: none (front hemisphere only);
//! −180–180: none (the whole sphere). Vertical angles: type C within 0…180°, types A and B
//! within −90…90°; outside the tabulated range the intensity is 0.

use super::error::PhotometryError;
use super::luminous::LuminousOpening;
use super::symmetry::{PLANE_C0, PLANE_C90, full_turn, signed};
use super::system::System;
use super::table::{Column, IntensityDistribution, check_intensity};
use super::tilt::Tilt;
use super::tokens::Tokens;
use std::path::Path;

/// One foot, m (the units type 1 of the luminous opening's sizes).
const FOOT: f64 = 0.3048;

/// Reads an IES file from the text of `file`.
pub fn parse(file: &Path, text: &str) -> Result<IntensityDistribution, PhotometryError> {
    let lines: Vec<&str> = text.lines().collect();
    let year = version(file, lines.first().copied().unwrap_or(""))?;
    let Some(at) = lines.iter().skip(1).position(|l| l.trim_start().to_ascii_uppercase().starts_with("TILT=")) else {
        let message = "expected a TILT= line (TILT=NONE or TILT=INCLUDE) after the keyword lines, found none";
        return Err(PhotometryError::at(file, lines.len().max(1), message));
    };
    let tilt_line = at + 1;
    let spec = lines[tilt_line].trim_start()[5..].trim().to_ascii_uppercase();
    let mut tokens = Tokens::new(file, lines[tilt_line + 1..].iter().copied(), tilt_line + 2);
    let tilt = match spec.as_str() {
        "NONE" => None,
        "INCLUDE" => Some(tilt(&mut tokens)?),
        _ => {
            let message = format!(
                "expected TILT=NONE or TILT=INCLUDE, got TILT={spec} (tilt data in a separate file is not \
                 supported; include it in the file with TILT=INCLUDE)"
            );
            return Err(PhotometryError::at(file, tilt_line + 1, message));
        }
    };
    let lamps = tokens.integer("the number of lamps", 1..=i64::MAX)?;
    let lumens = tokens.number(&|| "the lumens per lamp".into())?;
    if lumens <= 0.0 && lumens != -1.0 {
        return Err(
            tokens.error(format!("expected the lumens per lamp (> 0, or −1 for absolute photometry), got {lumens}"))
        );
    }
    let multiplier = positive(&mut tokens, "the candela multiplier")?;
    let multiplier_line = tokens.line();
    let n_v = tokens.integer("the number of vertical angles", 2..=100_000)? as usize;
    let n_h = tokens.integer("the number of horizontal angles", 1..=100_000)? as usize;
    let kind = match tokens.integer("the photometric type (1 = C, 2 = B, 3 = A)", 1..=3)? {
        1 => System::C,
        2 => System::B,
        _ => System::A,
    };
    let metres = match tokens.integer("the units type (1 = feet, 2 = metres)", 1..=2)? {
        1 => FOOT,
        _ => 1.0,
    };
    let mut size = [0.0; 3];
    for (value, what) in size.iter_mut().zip(["the luminous opening's width", "its length", "its height"]) {
        *value = tokens.number(&|| what.to_string())? * metres;
    }
    let ballast = positive(&mut tokens, "the ballast factor")?;
    let photometric_factor = if year <= 1995 {
        positive(&mut tokens, "the ballast-lamp photometric factor")?
    } else {
        tokens.number(&|| "the future-use field after the ballast factor".into())?;
        1.0
    };
    tokens.number(&|| "the input watts".into())?;

    let (low, high) = if kind == System::C { (0.0, 180.0) } else { (-90.0, 90.0) };
    let vertical = angles(&mut tokens, n_v, "vertical", low, high)?;
    let horizontal = angles(&mut tokens, n_h, "horizontal", -360.0, 360.0)?;
    let layout = layout(kind, &horizontal).map_err(|message| tokens.error(message))?;
    let mut columns: Vec<Column> = Vec::with_capacity(n_h);
    for &h in &horizontal {
        let mut column = Vec::with_capacity(n_v);
        for j in 0..n_v {
            let what = || format!("candela value {} of {n_v} for horizontal angle {h}°", j + 1);
            let c = tokens.number(&what)?;
            check_intensity(c, &what()).map_err(|m| tokens.error(m))?;
            column.push(c);
        }
        columns.push((h, column));
    }
    if let Some((line, token)) = tokens.rest() {
        let message = format!(
            "unexpected '{token}' after the {n_h} × {n_v} candela values: the counts of vertical and \
             horizontal angles do not match the data"
        );
        return Err(PhotometryError::at(file, line, message));
    }

    let (polar, columns) = match kind {
        System::C => (vertical, columns),
        _ => {
            let polar = vertical.iter().rev().map(|v| 90.0 - v).collect();
            (polar, columns.into_iter().map(|(h, c)| (h, c.into_iter().rev().collect())).collect())
        }
    };
    let columns = if layout.signed { signed(columns, layout.mirrors) } else { full_turn(columns, layout.mirrors) };
    let mut table = IntensityDistribution::new(kind, columns, polar, layout.periodic);
    table.scale(multiplier * ballast * photometric_factor);
    if !table.is_finite() {
        let message = format!(
            "the candela values times the candela multiplier {multiplier:e}, the ballast factor {ballast:e} and the \
             photometric factor {photometric_factor:e} overflow double precision"
        );
        return Err(PhotometryError::at(file, multiplier_line, message));
    }
    let stated = lamps as f64 * lumens;
    if lumens > 0.0 && !stated.is_finite() {
        return Err(PhotometryError::at(file, multiplier_line, format!("{lamps} lamps of {lumens:e} lm overflow")));
    }
    table.tilt = tilt;
    table.stated_flux = (lumens > 0.0).then_some(stated);
    table.lamp_flux = table.stated_flux;
    table.luminous = LuminousOpening::of_ies(size[0], size[1], size[2]);
    table.description = format!("IES LM-63-{year}, type {kind:?}, {}", layout.name);
    Ok(table)
}

/// The year of the version line.
fn version(file: &Path, first: &str) -> Result<u32, PhotometryError> {
    let tag = first.trim_start_matches('\u{feff}').trim();
    match tag.to_ascii_uppercase().as_str() {
        "IESNA:LM-63-1995" | "IESNA91" => Ok(1995),
        "IESNA:LM-63-2002" => Ok(2002),
        "IES:LM-63-2019" => Ok(2019),
        _ => Err(PhotometryError::at(
            file,
            1,
            format!("expected the version line IESNA:LM-63-1995, IESNA:LM-63-2002 or IES:LM-63-2019, got '{tag}'"),
        )),
    }
}

/// The `TILT=INCLUDE` record.
fn tilt(tokens: &mut Tokens) -> Result<Tilt, PhotometryError> {
    let geometry = tokens.integer("the lamp-to-luminaire geometry of the tilt data", 1..=3)? as u8;
    let n = tokens.integer("the number of tilt angles", 1..=100_000)? as usize;
    let angles = angles(tokens, n, "tilt", 0.0, 180.0)?;
    let mut factors = Vec::with_capacity(n);
    for i in 0..n {
        let f = tokens.number(&|| format!("tilt factor {} of {n}", i + 1))?;
        if f < 0.0 {
            return Err(tokens.error(format!("expected tilt factor {} of {n} (at least 0), got {f}", i + 1)));
        }
        factors.push(f);
    }
    Ok(Tilt { geometry, angles, factors })
}

fn positive(tokens: &mut Tokens, what: &str) -> Result<f64, PhotometryError> {
    let x = tokens.number(&|| what.to_string())?;
    if x <= 0.0 {
        return Err(tokens.error(format!("expected {what} (greater than 0), got {x}")));
    }
    Ok(x)
}

/// `n` strictly increasing angles within `[low, high]`.
fn angles(tokens: &mut Tokens, n: usize, what: &str, low: f64, high: f64) -> Result<Vec<f64>, PhotometryError> {
    let mut out: Vec<f64> = Vec::with_capacity(n);
    for i in 0..n {
        let a = tokens.number(&|| format!("{what} angle {} of {n}", i + 1))?;
        if !(low..=high).contains(&a) {
            return Err(tokens.error(format!("expected {what} angle {} of {n} within {low}…{high}°, got {a}", i + 1)));
        }
        if let Some(&before) = out.last()
            && a <= before
        {
            return Err(tokens.error(format!(
                "{what} angles must increase: {what} angle {} of {n} is {a}°, after {before}°",
                i + 1
            )));
        }
        out.push(a);
    }
    Ok(out)
}

/// How the stored horizontal angles complete to the table.
struct Layout {
    mirrors: &'static [f64],
    periodic: bool,
    /// Azimuths kept signed, in `[−180, 180)` (types A and B).
    signed: bool,
    name: &'static str,
}

/// The symmetry that the first and last horizontal angle imply.
fn layout(kind: System, h: &[f64]) -> Result<Layout, String> {
    let (first, last) = (h[0], h[h.len() - 1]);
    let is = |a: f64, b: f64| first == a && last == b;
    let found = if kind == System::C {
        if h.len() == 1 {
            Some((&[][..], true, "axial symmetry"))
        } else if is(0.0, 90.0) {
            Some((&[PLANE_C0, PLANE_C90][..], true, "quadrant symmetry (0–90°)"))
        } else if is(0.0, 180.0) {
            Some((&[PLANE_C0][..], true, "bilateral symmetry about the C0–C180 plane"))
        } else if is(90.0, 270.0) {
            Some((&[PLANE_C90][..], true, "bilateral symmetry about the C90–C270 plane"))
        } else if first == 0.0 && last > 180.0 && last <= 360.0 {
            Some((&[][..], true, "no symmetry"))
        } else {
            None
        }
    } else if is(0.0, 90.0) {
        Some((&[PLANE_C0][..], false, "lateral symmetry (0–90°)"))
    } else if is(-90.0, 90.0) {
        Some((&[][..], false, "no symmetry (front hemisphere)"))
    } else if is(-180.0, 180.0) {
        Some((&[][..], true, "no symmetry (whole sphere)"))
    } else {
        None
    };
    let Some((mirrors, periodic, name)) = found else {
        let known = if kind == System::C {
            "type C: one angle, 0–90, 0–180, 90–270, or 0 to more than 180 up to 360"
        } else {
            "types A and B: 0–90, −90–90 or −180–180"
        };
        return Err(format!(
            "the horizontal angles {first}…{last}° imply no known symmetry ({known}) in a type {kind:?} file"
        ));
    };
    Ok(Layout { mirrors, periodic, signed: kind != System::C, name })
}
