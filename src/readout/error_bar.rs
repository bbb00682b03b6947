//! A probe reading's error bar (`docs/design.md` §5, "A reading's error bar", (5.5)): how far
//! the reading could be from the exact solution of the equation, estimated from the
//! equation's own residual at the points the probe sees.
//!
//! The field `L_h` misses the exact `L` by `e = L_h − L = −(I − K)⁻¹ r`, where
//! `r = (L_e + K L_h) − L_h` is the residual of one more bounce evaluated exactly. At the
//! points a probe sees, `r` is the luminance gathered there from the field
//! (`luminance::gathered`, exact point-to-leaf factors and rays) less the field's own value.
//! Its illuminance at the probe is estimated over [`RAYS`] stratified cosine-distributed
//! directions:
//!
//! `ΔE = (π/M) Σ_r (L_gathered(y_r) − L_h(y_r))`, with its standard error `σ`;
//!
//! `(I − K)⁻¹` is taken as the gain `1/(1 − ρ̄)` of the seen points' mean albedo `ρ̄` (a miss
//! or a black point counting 0, at most [`MOST_ALBEDO`]), so the plain reading errs by about
//! `−ΔE/(1 − ρ̄)`, and the reading corrected near geometry (5.4), which already took `ΔE_near`
//! of it, by `ΔE_near − ΔE/(1 − ρ̄)`. The error bar is
//!
//! `δE = |ΔE_near − ΔE/(1 − ρ̄)| + 2σ`.
//!
//! It is a bar, not a correction: with 64 rays its noise (`2σ`, 1.3 % of the reading on
//! average on the Cornell box's hard probes, 1.9 % on the open box's) exceeds the error it finds on most probes; added to the reading it would
//! make the Cornell box's hard probes worse (`docs/accuracy.md`, "Error bars"). Each ray
//! costs a gather, so a probe costs [`RAYS`] gathers; grids have no bar.

use crate::geometry::cosine_direction;
use crate::model::Model;
use crate::progress::Progress;
use crate::random::Stratified;
use crate::readout::field::Field;
use crate::readout::gather::Receiver;
use crate::readout::glossy::{ModelSurroundings, is_diffuse, stream};
use crate::readout::luminance::gathered;
use crate::readout::probe::ProbeReading;
use crate::scene::ProbeKind;
use glam::DVec3;
use rayon::prelude::*;
use std::f64::consts::PI;

/// Directions the residual is estimated over, a probe.
pub const RAYS: usize = 64;

/// The largest mean albedo the gain `1/(1 − ρ̄)` is taken at (a gain of 10).
pub const MOST_ALBEDO: f64 = 0.9;

/// The one-bounce residual's illuminance at a point: `ΔE` (lx), its standard error `σ` (lx),
/// and the mean albedo `ρ̄` of the points seen.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Residual {
    /// `ΔE`, lx.
    pub illuminance: f64,
    /// `σ`, lx.
    pub standard_error: f64,
    /// `ρ̄`.
    pub albedo: f64,
}

impl Residual {
    /// `δE` for a reading that was corrected near geometry by `correction` lx.
    pub fn error_bar(&self, correction: f64) -> f64 {
        let gain = 1.0 / (1.0 - self.albedo.min(MOST_ALBEDO));
        (correction - gain * self.illuminance).abs() + 2.0 * self.standard_error
    }
}

/// Sets the error bar of every point sensor's and luminance meter's reading (the
/// cylindrical kinds keep none), telling `progress` of each; a signal's stop leaves the
/// rest without (`crate::interrupt`: the caller checks).
pub fn estimate_errors(readings: &mut [ProbeReading], model: &Model, field: &Field, progress: &dyn Progress) {
    progress.begin("error bars", readings.len() as u64);
    for r in readings.iter_mut().take_while(|_| !crate::interrupt::asked()) {
        if matches!(r.kind, ProbeKind::Point | ProbeKind::LuminanceMeter { .. }) {
            r.error = Some(residual(model, field, r.position, r.normal, RAYS).error_bar(r.correction));
        }
        progress.advance(1);
    }
    progress.end();
}

/// The residual at `p` on a receiver facing the unit `n`, over `rays` directions (a
/// signal's stop leaves the rays after it unread: `crate::interrupt`).
pub fn residual(model: &Model, field: &Field, p: DVec3, n: DVec3, rays: usize) -> Residual {
    let at = Receiver::at(model, p, n);
    let stored = ModelSurroundings::new(model, field);
    let set = Stratified::new(rays, &mut stream(p, n));
    let samples: Vec<(f64, f64)> = (0..rays)
        .into_par_iter()
        .map(|r| {
            if crate::interrupt::asked() {
                return (0.0, 0.0);
            }
            let [u, v] = set.point(r);
            seen(&stored, p, at.frame.world(cosine_direction(u, v)), at.ignore)
        })
        .collect();
    let m = rays as f64;
    let mean = samples.iter().map(|s| s.0).sum::<f64>() / m;
    let variance = samples.iter().map(|s| (s.0 - mean).powi(2)).sum::<f64>() / (m - 1.0).max(1.0);
    let albedo = samples.iter().map(|s| s.1).sum::<f64>() / m;
    Residual { illuminance: mean, standard_error: (variance / m).sqrt(), albedo }
}

/// `(π (L_gathered − L_h), ρ)` of the point `p` sees along `w` (ignoring face `ignore`),
/// `L_h` as `stored` holds it:
/// zero for a miss, the back of a surface, and a surface that is not Lambertian (a glossy
/// surface's reading is relit already, a mirror's is its images').
fn seen(stored: &ModelSurroundings, p: DVec3, w: DVec3, ignore: u32) -> (f64, f64) {
    let (model, field) = (stored.model, stored.field);
    let sphere = model.kernel.directions.is_sphere();
    let Some((j, y)) = model.faces.landing_patch(&model.mesh, &model.visibility, p, w, ignore, sphere) else {
        return (0.0, 0.0);
    };
    let s = &model.mesh.patches[j];
    if s.normal.dot(w) >= 0.0 || !is_diffuse(&model.materials[s.material as usize]) {
        return (0.0, 0.0);
    }
    let albedo = model.kernel.blocks[model.kernel.patch_material[j] as usize].albedo(0, &model.kernel.directions).0;
    (PI * (gathered(model, field, j, y, -w) - stored.stored(j, w)), albedo)
}
