//! Point sensors (`[[probe]]`): luminance (cd/m²) and illuminance (lx) at an exact point,
//! gathered from the solved field rather than read off the patch that holds the point.
//!
//! The light arriving at `p` is gathered per direction cell `d` of a frame at `p`:
//! `I_d(p) = Σ_j Σ_m L_j(m) F_{dA(p)→P_j}^{d,m} V(p, P_j)` (the exact contour-integral form
//! factor, split by cells as in the kernel, and a visibility fraction from rays to
//! stratified points of `P_j`); the illuminance is `E = π Σ_d I_d`. A probe on a surface
//! (within `1e-4` of the scene's size, facing the same way) reads that surface's outgoing
//! luminance along its normal, `L0(k) + Σ_d ρ̄(k,d) I_d` (plus the transmitted light
//! gathered on the back side of a transmitting surface); a probe in free space reads what a
//! luminance meter at the point aimed along the normal would: the outgoing luminance,
//! gathered the same way, of the first surface point the normal meets, towards the probe
//! (0 when it meets nothing).

use crate::field::Field;
use crate::geometry::{Frame, NO_TWIN};
use crate::kernel::contour::point_to_polygon;
use crate::kernel::form_factor::{Binning, binned_point};
use crate::kernel::occlusion::{POINTS, sample_points};
use crate::model::Model;
use crate::scene::Probe;
use crate::visibility::NO_FACE;
use glam::DVec3;
use rayon::prelude::*;
use std::f64::consts::PI;

/// One probe's reading.
#[derive(Debug, Clone, PartialEq)]
pub struct ProbeReading {
    pub name: String,
    pub position: DVec3,
    pub normal: DVec3,
    /// cd/m².
    pub luminance: f64,
    /// lx, on a receiver at `position` facing `normal`.
    pub illuminance: f64,
    /// The patch the probe lies on, if any.
    pub patch: Option<usize>,
}

/// Reads every probe from a solved field.
pub fn read_probes(probes: &[Probe], model: &Model, field: &Field) -> Vec<ProbeReading> {
    probes.iter().map(|p| read(p, model, field)).collect()
}

/// Illuminance, lx, on a receiver at `p` facing the unit `n` (on a surface or in free space).
pub fn illuminance_at(model: &Model, field: &Field, p: DVec3, n: DVec3) -> f64 {
    PI * incident_at(model, field, p, n).1.iter().sum::<f64>()
}

/// The patch `p` lies on (if any) and the light arriving at `p` per cell of its frame.
fn incident_at(model: &Model, field: &Field, p: DVec3, n: DVec3) -> (Option<usize>, Vec<f64>) {
    let patch = patch_under(model, p, n);
    let frame = patch.map_or_else(|| Frame::around(n), |i| model.mesh.patches[i].frame());
    let ignore = patch.map_or(NO_FACE, |i| model.mesh.patches[i].face);
    (patch, gather(model, field, p, &frame, ignore))
}

fn read(probe: &Probe, model: &Model, field: &Field) -> ProbeReading {
    let (p, n) = (probe.position, probe.normal);
    let (patch, incident) = incident_at(model, field, p, n);
    let illuminance = PI * incident.iter().sum::<f64>();
    let luminance = match patch {
        Some(i) => outgoing(model, field, i, p, n, &incident),
        None => model
            .visibility
            .closest_hit(p, n, NO_FACE)
            .and_then(|hit| {
                let q = p + n * hit.distance;
                let i = model.mesh.patches.iter().position(|s| s.face == hit.face && s.normal.dot(n) < 0.0)?;
                let s = &model.mesh.patches[i];
                let incident = gather(model, field, q, &s.frame(), s.face);
                Some(outgoing(model, field, i, q, -n, &incident))
            })
            .unwrap_or(0.0),
    };
    ProbeReading { name: probe.name.clone(), position: p, normal: n, luminance, illuminance, patch }
}

/// Outgoing luminance of patch `i` at point `q` towards `direction`, from the light
/// `incident` on it per cell (and, for a transmitter, the light gathered on its back).
fn outgoing(model: &Model, field: &Field, i: usize, q: DVec3, direction: DVec3, incident: &[f64]) -> f64 {
    let kernel = &model.kernel;
    let patch = &model.mesh.patches[i];
    let k = kernel.directions.lookup(patch.frame().local(direction));
    let block = &kernel.blocks[kernel.patch_material[i] as usize];
    let mut l =
        model.l0[i * kernel.cells() + k] + incident.iter().enumerate().map(|(d, e)| block.at(k, d) * e).sum::<f64>();
    if block.transmits() && patch.twin != NO_TWIN {
        let back = &model.mesh.patches[patch.twin as usize];
        let through = gather(model, field, q, &back.frame(), back.face);
        l += through.iter().enumerate().map(|(d, e)| block.transmit_at(k, d).unwrap_or(0.0) * e).sum::<f64>();
    }
    l
}

/// `I_d(p)`: the light arriving at `p` per cell of `frame`, ignoring face `ignore`.
pub fn gather(model: &Model, field: &Field, p: DVec3, frame: &Frame, ignore: u32) -> Vec<f64> {
    let directions = &model.kernel.directions;
    let cells = directions.len();
    let binning = Binning::new(directions);
    model
        .mesh
        .patches
        .par_iter()
        .enumerate()
        .fold(
            || (vec![0.0; cells], Vec::new()),
            |(mut sum, mut bins), (j, s)| {
                if s.face == ignore || point_to_polygon(p, frame.normal, &s.polygon) <= 0.0 {
                    return (sum, bins);
                }
                let seen =
                    sample_points(s).iter().filter(|&&y| model.visibility.visible(p, y, [ignore, s.face])).count();
                if seen == 0 {
                    return (sum, bins);
                }
                let v = seen as f64 / POINTS as f64;
                bins.clear();
                binned_point(p, frame, s, &binning, &mut bins);
                for &(d, m, f) in &bins {
                    sum[d as usize] += v * f * field.at(j, m as usize);
                }
                (sum, bins)
            },
        )
        .map(|(sum, _)| sum)
        .reduce(|| vec![0.0; cells], |a, b| a.iter().zip(&b).map(|(x, y)| x + y).collect())
}

/// The patch that `p` lies on, facing `n`, if any.
fn patch_under(model: &Model, p: DVec3, n: DVec3) -> Option<usize> {
    let delta = 1e-4 * model.mesh.extent();
    let hit = model.visibility.closest_hit(p + n * delta, -n, NO_FACE)?;
    if hit.distance > 2.0 * delta {
        return None;
    }
    model.mesh.patches.iter().position(|s| s.face == hit.face && s.normal.dot(n) > 0.5)
}
