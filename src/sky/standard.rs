//! The relative luminance distributions of the CIE skies: the 15 CIE standard general
//! skies (ISO 15469:2004 / CIE S 011/E:2003) and the CIE traditional overcast sky
//! (Moon & Spencer 1942, CIE 1955), `docs/daylight.md`.
//!
//! A general sky is the product of a gradation `φ(Z) = 1 + a exp(b / cos Z)` (`φ(π/2) = 1`)
//! and an indicatrix `f(χ) = 1 + c (exp(dχ) − exp(dπ/2)) + e cos²χ`, where `Z` is the
//! element's zenith angle and `χ` its angular distance from the sun:
//! `L/L_z = f(χ) φ(Z) / (f(Z_s) φ(0))`. The traditional overcast sky is
//! `L/L_z = (1 + 2 cos Z)/3`, independent of the sun.

use glam::DVec3;
use std::f64::consts::FRAC_PI_2;

/// The gradation and indicatrix parameters `a, b, c, d, e` of one standard general sky.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Parameters {
    /// Gradation parameter `a`.
    pub a: f64,
    /// Gradation parameter `b`.
    pub b: f64,
    /// Indicatrix parameter `c`.
    pub c: f64,
    /// Indicatrix parameter `d`.
    pub d: f64,
    /// Indicatrix parameter `e`.
    pub e: f64,
}

/// The 15 standard general skies of CIE S 011 (Table 1), type 1 first: 1–4 overcast, 5
/// uniform, 6–11 partly cloudy, 12 the CIE standard clear sky, 13–15 cloudless turbid.
pub const GENERAL: [Parameters; 15] = [
    Parameters { a: 4.0, b: -0.70, c: 0.0, d: -1.0, e: 0.00 },
    Parameters { a: 4.0, b: -0.70, c: 2.0, d: -1.5, e: 0.15 },
    Parameters { a: 1.1, b: -0.8, c: 0.0, d: -1.0, e: 0.00 },
    Parameters { a: 1.1, b: -0.8, c: 2.0, d: -1.5, e: 0.15 },
    Parameters { a: 0.0, b: -1.0, c: 0.0, d: -1.0, e: 0.00 },
    Parameters { a: 0.0, b: -1.0, c: 2.0, d: -1.5, e: 0.15 },
    Parameters { a: 0.0, b: -1.0, c: 5.0, d: -2.5, e: 0.30 },
    Parameters { a: 0.0, b: -1.0, c: 10.0, d: -3.0, e: 0.45 },
    Parameters { a: -1.0, b: -0.55, c: 2.0, d: -1.5, e: 0.15 },
    Parameters { a: -1.0, b: -0.55, c: 5.0, d: -2.5, e: 0.30 },
    Parameters { a: -1.0, b: -0.55, c: 10.0, d: -3.0, e: 0.45 },
    Parameters { a: -1.0, b: -0.32, c: 10.0, d: -3.0, e: 0.45 },
    Parameters { a: -1.0, b: -0.32, c: 16.0, d: -3.0, e: 0.30 },
    Parameters { a: -1.0, b: -0.15, c: 16.0, d: -3.0, e: 0.30 },
    Parameters { a: -1.0, b: -0.15, c: 24.0, d: -2.8, e: 0.15 },
];

/// The closed set of relative sky luminance distributions.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Distribution {
    /// Standard general sky `1..=15` of CIE S 011.
    General(u8),
    /// The CIE traditional overcast sky, `(1 + 2 cos Z)/3` (the 16th column of CIE 171's tables).
    Overcast,
}

impl Distribution {
    /// The distribution named in a case file: `1`–`15`, `"overcast"` (traditional),
    /// `"clear"` (type 12) or `"uniform"` (type 5).
    pub fn parse(name: &str) -> Option<Distribution> {
        match name {
            "overcast" => Some(Distribution::Overcast),
            "clear" => Some(Distribution::General(12)),
            "uniform" => Some(Distribution::General(5)),
            _ => name.parse::<u8>().ok().filter(|t| (1..=15).contains(t)).map(Distribution::General),
        }
    }

    /// The luminance depends on where the sun is (CIE S 011's indicatrix `c` or `e` is not
    /// 0): every general sky but types 1, 3 and 5 (uniform); not the traditional overcast.
    pub fn uses_sun(&self) -> bool {
        match self {
            Distribution::Overcast => false,
            Distribution::General(t) => {
                let p = GENERAL[(*t as usize).clamp(1, 15) - 1];
                p.c != 0.0 || p.e != 0.0
            }
        }
    }

    /// The names [`Distribution::parse`] accepts.
    pub const NAMES: &'static str = "1 to 15 (the CIE standard general skies), \"overcast\", \"clear\" or \"uniform\"";

    /// `L/L_z` towards the unit direction `l` (`l.y > 0`, y up) with the sun towards the
    /// unit `sun`.
    pub fn relative(&self, l: DVec3, sun: DVec3) -> f64 {
        let cos_z = l.y.clamp(0.0, 1.0);
        match self {
            Distribution::Overcast => (1.0 + 2.0 * cos_z) / 3.0,
            Distribution::General(t) => {
                let p = GENERAL[(*t as usize).clamp(1, 15) - 1];
                let chi = l.dot(sun).clamp(-1.0, 1.0).acos();
                let z_sun = sun.y.clamp(-1.0, 1.0).acos();
                indicatrix(&p, chi) * gradation(&p, cos_z) / (indicatrix(&p, z_sun) * gradation(&p, 1.0))
            }
        }
    }
}

/// `φ(Z) = 1 + a exp(b / cos Z)`, 1 at the horizon.
pub fn gradation(p: &Parameters, cos_z: f64) -> f64 {
    if cos_z <= 0.0 { 1.0 } else { 1.0 + p.a * (p.b / cos_z).exp() }
}

/// `f(χ) = 1 + c (exp(dχ) − exp(dπ/2)) + e cos²χ`.
pub fn indicatrix(p: &Parameters, chi: f64) -> f64 {
    1.0 + p.c * ((p.d * chi).exp() - (p.d * FRAC_PI_2).exp()) + p.e * chi.cos().powi(2)
}
