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
//! costs a gather, so a probe costs [`RAYS`] gathers; in each, a patch of small light is
//! seen by one ray ([`ONE_RAY`]), and a run of such patches by one ray together (`runs.rs`),
//! unbiased, its noise in `σ`. A cylindrical probe's reading is the
//! mean over vertical planes (`cylindrical.rs`): its [`RAYS`] directions are shared among
//! them and their samples pooled, the estimate of the mean (not corrected, `ΔI = 0`). A
//! grid's points pool fewer directions each with their neighbours' (`grid_error.rs`).

use crate::geometry::cosine_direction;
use crate::model::Model;
use crate::progress::{Progress, Silent};
use crate::random::Stratified;
use crate::readout::cut::Cut;
use crate::readout::cylindrical::planes;
use crate::readout::field::Field;
use crate::readout::gather::Receiver;
use crate::readout::glossy::{ModelSurroundings, is_diffuse, stream};
use crate::readout::lit::Lit;
use crate::readout::luminance::{RELIT_SHADOW_CUT, gathered_each};
use crate::readout::probe::ProbeReading;
use crate::scene::ProbeKind;
use glam::DVec3;
use rayon::prelude::*;
use std::f64::consts::PI;

/// Directions the residual is estimated over, a probe.
pub const RAYS: usize = 64;

/// A patch sends the residual's gather at a point seen less than this fraction of all the
/// light the point would receive unoccluded is seen by one ray to one of its points at
/// random (`Cut::sampled`): unbiased, and its noise is in the samples' spread, `σ`.
pub const ONE_RAY: f64 = 1e-4;

/// The largest mean albedo the gain `1/(1 − ρ̄)` is taken at (a gain of 10).
pub const MOST_ALBEDO: f64 = 0.9;

/// One direction's sample of the residual: `π (L_gathered − L_h)` at the point it meets, lx,
/// and that point's albedo (both 0 for a miss, a back face, a surface that is not Lambertian).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Sample {
    /// `π r(y)`, lx.
    pub illuminance: f64,
    /// `ρ(y)`.
    pub albedo: f64,
}

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
    /// The residual of `samples` (at least one) pooled with equal weights: their mean, its
    /// standard error from their spread, and their mean albedo.
    pub fn pooled<'a>(samples: impl Iterator<Item = &'a Sample> + Clone) -> Residual {
        let (m, sum, albedo) =
            samples.clone().fold((0.0, 0.0, 0.0), |(m, s, a), x| (m + 1.0, s + x.illuminance, a + x.albedo));
        let mean = sum / m;
        let variance = samples.map(|s| (s.illuminance - mean).powi(2)).sum::<f64>() / (m - 1.0).max(1.0);
        Residual { illuminance: mean, standard_error: (variance / m).sqrt(), albedo: albedo / m }
    }

    /// `δE` for a reading that was corrected near geometry by `correction` lx.
    pub fn error_bar(&self, correction: f64) -> f64 {
        let gain = 1.0 / (1.0 - self.albedo.min(MOST_ALBEDO));
        (correction - gain * self.illuminance).abs() + 2.0 * self.standard_error
    }
}

/// Sets the error bar of every probe's reading, telling `progress` of each; a signal's stop
/// leaves the rest without (`crate::interrupt`: the caller checks).
pub fn estimate_errors(readings: &mut [ProbeReading], model: &Model, field: &Field, progress: &dyn Progress) {
    let samples = probe_samples(readings, model, &[Lit::own(model, field)], &[], progress);
    set_errors(readings, &samples[0]);
}

/// The residual's samples of every probe of `readings` ([`probe_rays`] each, probe after
/// probe), for each field of `lits` (`samples`: the gathers shared, cut by the rules of
/// `by`), telling `progress` of each probe; a signal's stop leaves the samples after it zero.
pub fn probe_samples(
    readings: &[ProbeReading],
    model: &Model,
    lits: &[Lit],
    by: &[&Field],
    progress: &dyn Progress,
) -> Vec<Vec<Sample>> {
    progress.begin("error bars", readings.len() as u64);
    let total = readings.iter().map(probe_rays).sum();
    let mut all: Vec<Vec<Sample>> = lits.iter().map(|_| Vec::with_capacity(total)).collect();
    for r in readings {
        let receivers = receivers(r);
        let each = samples(model, lits, &receivers, RAYS / receivers.len(), by, &Silent);
        all.iter_mut().zip(each).for_each(|(all, s)| all.extend(s));
        progress.advance(1);
    }
    progress.end();
    all
}

/// Sets the error bar of every probe of `readings` from its samples in `samples` (as
/// [`probe_samples`] lays them out); the probes past the samples' end are left without.
pub fn set_errors(readings: &mut [ProbeReading], samples: &[Sample]) {
    let mut start = 0;
    for r in readings.iter_mut() {
        let Some(own) = samples.get(start..start + probe_rays(r)) else { return };
        r.error = Some(Residual::pooled(own.iter()).error_bar(r.correction));
        start += own.len();
    }
}

/// The samples a probe's bar pools: [`RAYS`] shared among its receivers.
pub fn probe_rays(r: &ProbeReading) -> usize {
    let receivers = receivers(r).len();
    RAYS / receivers * receivers
}

/// The receivers `(p, n)` a probe's illuminance is the mean of: its own for a point sensor
/// and a luminance meter, the vertical planes of the midpoint rule for the cylindrical
/// kinds (`cylindrical.rs`), among which the [`RAYS`] directions are shared.
fn receivers(r: &ProbeReading) -> Vec<(DVec3, DVec3)> {
    let planes = match r.kind {
        ProbeKind::Point | ProbeKind::LuminanceMeter { .. } => return vec![(r.position, r.normal)],
        ProbeKind::Cylindrical => planes(r.normal, None),
        ProbeKind::SemiCylindrical { axis } => planes(axis, Some(r.normal)),
    };
    planes.into_iter().map(|n| (r.position, n)).collect()
}

/// The residual at `p` on a receiver facing the unit `n`, over `rays` directions (a
/// signal's stop leaves the rays after it unread: `crate::interrupt`).
pub fn residual(model: &Model, field: &Field, p: DVec3, n: DVec3, rays: usize) -> Residual {
    Residual::pooled(samples(model, &[Lit::own(model, field)], &[(p, n)], rays, &[], &Silent)[0].iter())
}

/// The residual's samples over `rays` stratified cosine-distributed directions from each
/// receiver at `p` facing the unit `n` of `receivers`, receiver after receiver, for each
/// field of `lits` (a signal's stop leaves the rays after it unread, zero:
/// `crate::interrupt`); `progress` advances by one as each receiver's last direction is
/// read. The point a direction meets and the gather there are found once for all the
/// fields (`lit.rs`), cut along shadow edges by the rule of every field of `by` (`cut.rs`:
/// fields whose samples are summed), or of `lits` when it names none.
pub fn samples(
    model: &Model,
    lits: &[Lit],
    receivers: &[(DVec3, DVec3)],
    rays: usize,
    by: &[&Field],
    progress: &dyn Progress,
) -> Vec<Vec<Sample>> {
    let stored: Vec<ModelSurroundings> = lits.iter().map(|l| ModelSurroundings::new(model, l.field)).collect();
    let sets: Vec<(Receiver, Stratified)> = receivers
        .par_iter()
        .map(|&(p, n)| (Receiver::at(model, p, n), Stratified::new(rays, &mut stream(p, n))))
        .collect();
    let each: Vec<Vec<Sample>> = (0..receivers.len() * rays)
        .into_par_iter()
        .map(|k| {
            if crate::interrupt::asked() {
                return vec![Sample::default(); lits.len()];
            }
            let ((at, set), p) = (&sets[k / rays], receivers[k / rays].0);
            let [u, v] = set.point(k % rays);
            let sample = seen(model, lits, &stored, p, at.frame.world(cosine_direction(u, v)), at.ignore, by);
            if k % rays == rays - 1 {
                progress.advance(1);
            }
            sample
        })
        .collect();
    (0..lits.len()).map(|l| each.iter().map(|s| s[l]).collect()).collect()
}

/// The sample, for each field of `lits` (`stored` holding each as `L_h`), of the point `p`
/// sees along `w` (ignoring face `ignore`): zero for a miss, the back of a surface, and a
/// surface that is not Lambertian (a glossy surface's reading is relit already, a mirror's
/// is its images'); its gather cut by the rules of `by`.
fn seen(
    model: &Model,
    lits: &[Lit],
    stored: &[ModelSurroundings],
    p: DVec3,
    w: DVec3,
    ignore: u32,
    by: &[&Field],
) -> Vec<Sample> {
    let sphere = model.kernel.directions.is_sphere();
    let none = || vec![Sample::default(); lits.len()];
    let Some((j, y)) = model.faces.landing_patch(&model.mesh, &model.visibility, p, w, ignore, sphere) else {
        return none();
    };
    let s = &model.mesh.patches[j];
    if s.normal.dot(w) >= 0.0 || !is_diffuse(&model.materials[s.material as usize]) {
        return none();
    }
    let albedo = model.kernel.blocks[model.kernel.patch_material[j] as usize].albedo(0, &model.kernel.directions).0;
    let cut = Cut { fraction: RELIT_SHADOW_CUT, by, sampled: ONE_RAY };
    let gathered = gathered_each(model, lits, j, y, -w, &cut);
    let light = gathered.iter().zip(stored);
    light.map(|(g, stored)| Sample { illuminance: PI * (g - stored.stored(j, w)), albedo }).collect()
}
