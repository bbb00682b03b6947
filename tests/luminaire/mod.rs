//! Tests of luminaires in the system (`ugo::luminaire`): placement (aim, rotation, tilt,
//! multiplier), the source term `L0 = L_e + B·D` on Lambertian and glossy receivers, shadows,
//! energy, probes, and the CLI and HDF5 output.

mod cli;
mod placement;
mod render;
mod source_term;
mod trace;

use glam::DVec3;
use std::path::Path;
use ugo::luminaire::{Luminaire, LuminaireKind, PointLuminaire};
use ugo::photometry::{Distribution, read_ies};

/// A point luminaire named `name` at `position` aimed along `aim`.
pub fn point(name: &str, position: DVec3, aim: DVec3, distribution: Distribution) -> Luminaire {
    let kind = LuminaireKind::Point(PointLuminaire {
        position,
        aim: aim.normalize(),
        rotate_deg: 0.0,
        multiplier: 1.0,
        distribution,
        file: None,
    });
    Luminaire { name: name.into(), kind }
}

/// A synthetic photometric file of `tests/data/photometry/` as a distribution.
pub fn table(name: &str) -> Distribution {
    let path = Path::new("tests/data/photometry").join(name);
    Distribution::Table(Box::new(read_ies(&path).unwrap_or_else(|e| panic!("{e}"))))
}
