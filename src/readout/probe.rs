//! `[[probe]]` readings at exact points, gathered from the solved field (`gather.rs`)
//! rather than read off the patch that holds the point, one reading per kind:
//!
//! * `point`: the illuminance `E = π Σ_d (I_d + D_d)` (lx) on a receiver at the point facing
//!   the normal, and a luminance: on a surface (within `1e-4` of the scene's size, facing
//!   the same way) that surface's outgoing luminance along its normal; in free space what a
//!   luminance meter at the point aimed along the normal reads, with a vanishing field of
//!   view (`luminance::seen`: the first surface point the normal meets, towards the probe);
//! * `luminance_meter`: the mean luminance within its field of view (`meter.rs`), and the
//!   illuminance on a receiver at the point facing the viewing direction;
//! * `cylindrical`, `semi_cylindrical`: the illuminance of EN 12464-1 and EN 13201-2
//!   (`cylindrical.rs`); no luminance (NaN).
//!
//! Each reading keeps the part of its illuminance that comes directly from the luminaires.
//! A point sensor's and a luminance meter's illuminance (and a point sensor's luminance on a
//! surface, from the same light) are corrected near geometry (`correction.rs`,
//! `docs/design.md` (5.4)), and the reading keeps the correction; its error bar
//! (`error_bar.rs`, (5.5)) is a separate step, a gather per direction.

use crate::model::Model;
use crate::progress::Progress;
use crate::readout::correction::{Corrected, corrected};
use crate::readout::cylindrical::cylindrical;
use crate::readout::field::Field;
use crate::readout::gather::sum;
use crate::readout::luminance::{RELIT_RAYS, outgoing, seen};
use crate::readout::meter::mean_luminance;
use crate::scene::{Probe, ProbeKind};
use glam::DVec3;

/// One probe's reading.
#[derive(Debug, Clone, PartialEq)]
pub struct ProbeReading {
    /// The probe's name.
    pub name: String,
    /// What the probe reads.
    pub kind: ProbeKind,
    /// Where it reads, m.
    pub position: DVec3,
    /// The probe's direction (`Probe::normal`: normal, viewing direction, axis, or facing).
    pub normal: DVec3,
    /// cd/m² (NaN for the cylindrical kinds).
    pub luminance: f64,
    /// lx: on a receiver at `position` facing `normal` (a point sensor, a luminance meter),
    /// or the cylindrical or semi-cylindrical illuminance.
    pub illuminance: f64,
    /// The part of `illuminance` that comes directly from the luminaires, lx.
    pub direct: f64,
    /// The correction near geometry included in `illuminance` (`correction.rs`), lx; 0 for
    /// the cylindrical kinds, which are not corrected.
    pub correction: f64,
    /// The patch a point sensor lies on, if any.
    pub patch: Option<usize>,
    /// The illuminance's error bar, lx (`error_bar.rs`, `docs/design.md` (5.5)), once
    /// estimated: `read_probes` leaves it `None`, `error_bar::estimate_errors` sets it for a
    /// point sensor and a luminance meter.
    pub error: Option<f64>,
}

/// Reads every probe from a solved field, telling `progress` of each; a signal's stop
/// leaves the probes after it unread (`crate::interrupt`: the caller checks).
pub fn read_probes(probes: &[Probe], model: &Model, field: &Field, progress: &dyn Progress) -> Vec<ProbeReading> {
    progress.begin("probes", probes.len() as u64);
    let readings = probes
        .iter()
        .take_while(|_| !crate::interrupt::asked())
        .map(|p| {
            let reading = read(p, model, field);
            progress.advance(1);
            reading
        })
        .collect();
    progress.end();
    readings
}

fn read(probe: &Probe, model: &Model, field: &Field) -> ProbeReading {
    let (p, n) = (probe.position, probe.normal);
    let reading = |luminance, (illuminance, direct), correction, patch| ProbeReading {
        name: probe.name.clone(),
        kind: probe.kind,
        position: p,
        normal: n,
        luminance,
        illuminance,
        direct,
        correction,
        patch,
        error: None,
    };
    match probe.kind {
        ProbeKind::Point => {
            let light = corrected(model, field, p, n);
            reading(point_luminance(model, field, p, n, &light), light.illuminance(), light.correction, light.patch)
        }
        ProbeKind::LuminanceMeter { fov_deg } => {
            let light = corrected(model, field, p, n);
            reading(mean_luminance(model, field, p, n, fov_deg), light.illuminance(), light.correction, None)
        }
        ProbeKind::Cylindrical => reading(f64::NAN, cylindrical(model, field, p, n, None), 0.0, None),
        ProbeKind::SemiCylindrical { axis } => {
            reading(f64::NAN, cylindrical(model, field, p, axis, Some(n)), 0.0, None)
        }
    }
}

/// A point sensor's luminance: on a surface, its outgoing luminance from the corrected
/// light `light`; in free space, what a meter aimed along `n` reads.
fn point_luminance(model: &Model, field: &Field, p: DVec3, n: DVec3, light: &Corrected) -> f64 {
    match light.patch {
        Some(i) => outgoing(model, field, i, p, n, &sum(&light.incident, &light.direct)),
        None => seen(model, field, p, n, RELIT_RAYS),
    }
}
