//! Point sensors (`[[probe]]`): luminance (cd/m²) and illuminance (lx) at an exact point,
//! gathered from the solved field rather than read off the patch that holds the point.
//!
//! `E(p) = π Σ_j L_j(→p) F_{dA(p)→P_j} V(p, P_j)` with the exact contour-integral form
//! factor and a visibility fraction from rays to stratified points of `P_j`. A probe on
//! a surface (within `1e-4` of the scene's size, facing the same way) reads that
//! surface's outgoing luminance at the point, `L0 + ρ̄ E/π`; a probe in free space reads
//! what a luminance meter at the point aimed along the normal would: the outgoing
//! luminance, gathered the same way, of the first surface point the normal meets
//! (0 when it meets nothing).

use crate::field::Field;
use crate::kernel::contour::point_to_polygon;
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

fn read(probe: &Probe, model: &Model, field: &Field) -> ProbeReading {
    let (p, n) = (probe.position, probe.normal);
    let patch = patch_under(model, p, n);
    let e = illuminance(model, field, p, n, patch.map_or(NO_FACE, |i| model.mesh.patches[i].face));
    let luminance = match patch {
        Some(i) => outgoing(model, i, e),
        None => model
            .visibility
            .closest_hit(p, n, NO_FACE)
            .and_then(|hit| {
                let q = p + n * hit.distance;
                let i = model.mesh.patches.iter().position(|s| s.face == hit.face && s.normal.dot(n) < 0.0)?;
                let s = &model.mesh.patches[i];
                Some(outgoing(model, i, illuminance(model, field, q, s.normal, s.face)))
            })
            .unwrap_or(0.0),
    };
    ProbeReading { name: probe.name.clone(), position: p, normal: n, luminance, illuminance: e, patch }
}

/// Outgoing luminance of patch `i` at a point where the illuminance is `e` (one cell).
fn outgoing(model: &Model, i: usize, e: f64) -> f64 {
    let k = model.kernel.cells();
    let block = &model.kernel.blocks[model.kernel.patch_material[i] as usize];
    model.l0[i * k] + block.at(0, 0) * e / PI
}

/// Illuminance at `p` on a receiver facing `n`, gathered from every patch.
pub fn illuminance(model: &Model, field: &Field, p: DVec3, n: DVec3, ignore: u32) -> f64 {
    let directions = &model.kernel.directions;
    model
        .mesh
        .patches
        .par_iter()
        .enumerate()
        .map(|(j, s)| {
            let f = point_to_polygon(p, n, &s.polygon);
            if f <= 0.0 || s.face == ignore {
                return 0.0;
            }
            let points = sample_points(s);
            let seen = points.iter().filter(|&&y| model.visibility.visible(p, y, [ignore, s.face])).count();
            let towards = p - s.centroid;
            let local = DVec3::new(towards.dot(s.tangent), towards.dot(s.bitangent), towards.dot(s.normal));
            PI * field.at(j, directions.lookup(local.normalize())) * f * seen as f64 / POINTS as f64
        })
        .sum()
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
