//! [`IntensityDistribution`]: a table of candela over the angles `(a, θ)` of one
//! goniometric system ([`System`]), interpolated bilinearly, with its flux.
//!
//! Outside the tabulated polar range the intensity is 0 (a downlight's table ends at 90°).
//! In azimuth the table is either *periodic* (the symmetries of the file expanded to a
//! full turn; the last column is followed by the first, 360° on) or covers a range, the
//! intensity being 0 outside it (types A and B: the hemisphere behind the luminaire).
//!
//! The flux is the exact integral of the interpolant over the sphere,
//! `Φ = ∫∫ I(a, θ) sinθ dθ da`: per cell, the bilinear interpolant integrates in closed
//! form (trapezoid in `a`; in `θ` the weights `cosθ₀ − (sinθ₁ − sinθ₀)/h` and
//! `(sinθ₁ − sinθ₀)/h − cosθ₁` of the two end values, `h = θ₁ − θ₀`).

use super::luminous::LuminousOpening;
use super::system::System;
use super::tilt::Tilt;
use glam::DVec3;
use std::f64::consts::TAU;

/// A tabulated luminous intensity distribution in the luminaire frame (cd).
#[derive(Debug, Clone, PartialEq)]
pub struct IntensityDistribution {
    system: System,
    /// Azimuths `a`, degrees, strictly increasing, spanning less than 360°.
    azimuth: Vec<f64>,
    /// Polar angles `θ`, degrees, strictly increasing, within `[0, 180]`.
    polar: Vec<f64>,
    /// cd, column by column: `candela[i · polar.len() + j]` at `(azimuth[i], polar[j])`.
    candela: Vec<f64>,
    periodic: bool,
    /// Lamp output against the luminaire's tilt (IES `TILT=INCLUDE`).
    pub tilt: Option<Tilt>,
    /// The luminaire flux the file states, lm (none for absolute photometry).
    pub stated_flux: Option<f64>,
    /// The flux of the bare lamps the intensities are given for, lm (IES: lamps × lumens;
    /// EULUMDAT: the lamp sets' total); none for absolute photometry.
    pub lamp_flux: Option<f64>,
    /// The luminous opening the file sizes, if any (what the eye sees of the luminaire).
    pub luminous: Option<LuminousOpening>,
    /// What the file was, for reports (`"IES LM-63-2002, type C, 0–90° quadrant symmetry"`).
    pub description: String,
}

/// Most intensity a file may give one direction, as written: a source this intense in
/// every direction emits 1e20 lm, the largest flux a scene takes (`scene::check::MAGNITUDE`).
/// (A file's multipliers that take it further are refused at their own line.)
pub const MOST_CANDELA: f64 = 1e20 / (2.0 * TAU);

/// Checks one intensity `value` of a file: the message for the value's line when it is
/// negative or over [`MOST_CANDELA`]; `what` names it.
pub fn check_intensity(value: f64, what: &str) -> Result<(), String> {
    if value < 0.0 {
        return Err(format!("expected {what} (at least 0), got {value}"));
    }
    if value > MOST_CANDELA {
        return Err(format!(
            "expected {what} at most {MOST_CANDELA:.3e} (a source that intense all round emits 1e20 lm), got {value:e}"
        ));
    }
    Ok(())
}

/// One column of the table: an azimuth and the candela at every polar angle.
pub type Column = (f64, Vec<f64>);

impl IntensityDistribution {
    /// A table from its columns (sorted by azimuth, each as long as `polar`).
    pub fn new(system: System, columns: Vec<Column>, polar: Vec<f64>, periodic: bool) -> IntensityDistribution {
        let azimuth = columns.iter().map(|(a, _)| *a).collect();
        let candela = columns.into_iter().flat_map(|(_, c)| c).collect();
        IntensityDistribution {
            system,
            azimuth,
            polar,
            candela,
            periodic,
            tilt: None,
            stated_flux: None,
            lamp_flux: None,
            luminous: None,
            description: String::new(),
        }
    }

    /// Every candela value, scaled by `factor` (a file's multipliers).
    pub fn scale(&mut self, factor: f64) {
        self.candela.iter_mut().for_each(|c| *c *= factor);
    }

    /// Every intensity and the flux they integrate to are finite numbers (a file's
    /// values times its multipliers may overflow).
    pub fn is_finite(&self) -> bool {
        self.candela.iter().all(|c| c.is_finite()) && self.flux().is_finite()
    }

    /// The intensity towards a unit direction `l` of the luminaire frame, cd.
    pub fn intensity(&self, l: DVec3) -> f64 {
        let (a, theta) = self.system.angles(l);
        self.at(a, theta)
    }

    /// The interpolated intensity at `(a, θ)`, degrees; 0 outside the table.
    pub fn at(&self, a: f64, theta: f64) -> f64 {
        let Some((j0, j1, t)) = bracket(&self.polar, theta) else { return 0.0 };
        let Some((i0, i1, s)) = self.azimuth_bracket(a) else { return 0.0 };
        let m = self.polar.len();
        let value = |i: usize| self.candela[i * m + j0] * (1.0 - t) + self.candela[i * m + j1] * t;
        value(i0) * (1.0 - s) + value(i1) * s
    }

    /// The columns around azimuth `a` and the weight of the second one.
    fn azimuth_bracket(&self, a: f64) -> Option<(usize, usize, f64)> {
        let first = self.azimuth[0];
        let last = self.azimuth[self.azimuth.len() - 1];
        let a = first + (a - first).rem_euclid(360.0);
        if a <= last {
            return bracket(&self.azimuth, a);
        }
        if !self.periodic {
            return None;
        }
        let n = self.azimuth.len() - 1;
        Some((n, 0, (a - last) / (first + 360.0 - last)))
    }

    /// `Φ = ∫ I dω` of the interpolated table, lm (exact for the bilinear interpolant).
    pub fn flux(&self) -> f64 {
        let m = self.polar.len();
        let weights: Vec<(f64, f64)> = self
            .polar
            .windows(2)
            .map(|w| {
                let (t0, t1) = (w[0].to_radians(), w[1].to_radians());
                let mean_sin = (t1.sin() - t0.sin()) / (t1 - t0);
                (t0.cos() - mean_sin, mean_sin - t1.cos())
            })
            .collect();
        let column = |i: usize| -> f64 {
            let c = &self.candela[i * m..(i + 1) * m];
            weights.iter().enumerate().map(|(j, (w0, w1))| c[j] * w0 + c[j + 1] * w1).sum()
        };
        let n = self.azimuth.len();
        if n == 1 {
            return if self.periodic { TAU * column(0) } else { 0.0 };
        }
        let mut flux = 0.0;
        for i in 0..n - 1 {
            flux += (self.azimuth[i + 1] - self.azimuth[i]).to_radians() * 0.5 * (column(i) + column(i + 1));
        }
        if self.periodic {
            flux += (self.azimuth[0] + 360.0 - self.azimuth[n - 1]).to_radians() * 0.5 * (column(n - 1) + column(0));
        }
        flux
    }
}

/// The indices around `x` in the increasing `angles` and the weight of the second one;
/// none outside `[angles[0], angles[last]]`.
fn bracket(angles: &[f64], x: f64) -> Option<(usize, usize, f64)> {
    let last = angles.len() - 1;
    if !(angles[0]..=angles[last]).contains(&x) {
        return None;
    }
    let i = angles.partition_point(|&v| v <= x).clamp(1, last.max(1)) - 1;
    if i == last {
        return Some((i, i, 0.0));
    }
    Some((i, i + 1, (x - angles[i]) / (angles[i + 1] - angles[i])))
}
