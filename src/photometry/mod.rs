//! Photometric light sources: luminous intensity distributions `I(l)`, cd, in the
//! luminaire frame, given in closed form or read from IES LM-63 and EULUMDAT files
//! (`docs/photometry.md`).
//!
//! A luminaire's direct light is the source term of the patches it reaches,
//! `L0(i,k) = (1/π) ρ̄_i(k, d_s) E_s(i)` (`docs/design.md` §1, §3; built in `luminaire`); this
//! module owns only the distributions: the closed set [`Distribution`], the table
//! [`IntensityDistribution`] with its interpolation and exact flux, the goniometric systems
//! A, B and C ([`System`]), the symmetries files imply, tilt factors, and the two file
//! readers, the luminous opening they size ([`LuminousOpening`]), whose errors ([`PhotometryError`]) name the file, the line and what was
//! expected there. It knows nothing of scenes, meshes or TOML.
//!
//! The luminaire frame: `x` along the luminaire (C0), `y` across it (C90), `z` up; the
//! luminaire aims along `−z` (γ = 0).

mod error;
mod ies;
mod ldt;
mod luminous;
mod symmetry;
mod system;
mod table;
mod tilt;
mod tokens;

pub use error::PhotometryError;
pub use luminous::{FALLBACK_DIAMETER, LuminousOpening};
pub use system::System;
pub use table::{Column, IntensityDistribution};
pub use tilt::Tilt;

use glam::DVec3;
use std::f64::consts::PI;
use std::path::Path;

/// The closed set of intensity distributions of a point luminaire.
#[derive(Debug, Clone, PartialEq)]
pub enum Distribution {
    /// The same intensity, cd, in every direction; flux `4πI`.
    Isotropic {
        /// Intensity, cd.
        intensity: f64,
    },
    /// `I(γ) = I0 cosγ` below the luminaire's horizontal, 0 above; flux `π I0`.
    Lambertian {
        /// `I0`, the intensity along the aim, cd.
        peak: f64,
    },
    /// A table read from a photometric file.
    Table(Box<IntensityDistribution>),
}

impl Distribution {
    /// The intensity towards the unit direction `l` of the luminaire frame, cd.
    pub fn intensity(&self, l: DVec3) -> f64 {
        match self {
            Distribution::Isotropic { intensity } => *intensity,
            Distribution::Lambertian { peak } => peak * (-l.z).max(0.0),
            Distribution::Table(table) => table.intensity(l),
        }
    }

    /// What the eye sees of the luminaire: the file's luminous opening, else a sphere of
    /// [`FALLBACK_DIAMETER`].
    pub fn luminous(&self) -> LuminousOpening {
        let file = match self {
            Distribution::Table(table) => table.luminous,
            Distribution::Isotropic { .. } | Distribution::Lambertian { .. } => None,
        };
        file.unwrap_or(LuminousOpening::Sphere { diameter: FALLBACK_DIAMETER })
    }

    /// The luminous flux, lm.
    pub fn flux(&self) -> f64 {
        match self {
            Distribution::Isotropic { intensity } => 4.0 * PI * intensity,
            Distribution::Lambertian { peak } => PI * peak,
            Distribution::Table(table) => table.flux(),
        }
    }
}

/// Reads an IES LM-63 file.
pub fn read_ies(file: &Path) -> Result<IntensityDistribution, PhotometryError> {
    ies::parse(file, &read_text(file)?)
}

/// Reads an EULUMDAT file.
pub fn read_ldt(file: &Path) -> Result<IntensityDistribution, PhotometryError> {
    ldt::parse(file, &read_text(file)?)
}

/// Parses IES text as if read from `file` (for files written in code).
pub fn parse_ies(file: &Path, text: &str) -> Result<IntensityDistribution, PhotometryError> {
    ies::parse(file, text)
}

/// Parses EULUMDAT text as if read from `file`.
pub fn parse_ldt(file: &Path, text: &str) -> Result<IntensityDistribution, PhotometryError> {
    ldt::parse(file, text)
}

/// The file as text; bytes that are not UTF-8 (Latin-1 keyword text) are replaced.
fn read_text(file: &Path) -> Result<String, PhotometryError> {
    let bytes = std::fs::read(file).map_err(|e| PhotometryError::whole(file, format!("cannot read the file: {e}")))?;
    Ok(String::from_utf8_lossy(&bytes).into_owned())
}
