//! Backward estimates of the `[[probe]]` readings (`docs/design.md` §7), with the meaning of
//! `crate::readout::probe`: the luminance (cd/m²) a meter at the point aimed along the normal reads
//! (on a surface: that surface's outgoing luminance along its normal), and the illuminance
//! (lx) on a receiver at the point facing the normal, `E = ∫ L_in cosθ dω`.
//!
//! The illuminance combines next-event estimation towards the emitters with
//! cosine-distributed directions (each continued as a path), weighted by the power
//! heuristic: `E = π L_in(l)` per cosine direction (density `cosθ/π`); the luminaires'
//! direct light at the point is added exactly, and the sky through the openings is
//! sampled like the emitters (`openings.rs`).

use super::backward::{Start, TraceOptions, luminance_along, power_heuristic};
use super::openings::Openings;
use super::statistics::Tally;
use super::world::World;
use crate::geometry::Frame;
use crate::geometry::cosine_direction;
use crate::random::Rng;
use crate::scene::{Probe, ProbeKind};
use crate::visibility::{NO_FACE, standoff};
use glam::DVec3;
use rayon::prelude::*;
use std::f64::consts::{FRAC_1_PI, PI};

/// A probe's readings with their standard errors.
#[derive(Debug, Clone, PartialEq)]
pub struct ProbeEstimate {
    /// The probe's name.
    pub name: String,
    /// Luminance and its standard error, cd/m².
    pub luminance: (f64, f64),
    /// Illuminance and its standard error, lx.
    pub illuminance: (f64, f64),
}

/// Reads every point sensor (`kind = "point"`; the other kinds have no estimator here)
/// with `samples` paths for each quantity; probe `p`'s streams are keyed by `(seed, 2p)`
/// and `(seed, 2p + 1)`. `progress(paths)` hears of every [`REPORT`] paths done, `2 ×
/// samples` per point sensor in all. A signal's stop cuts the paths short
/// (`crate::interrupt`: the caller checks).
pub fn trace_probes(
    world: &World,
    probes: &[Probe],
    samples: usize,
    options: &TraceOptions,
    progress: &(dyn Fn(u64) + Sync),
) -> Vec<ProbeEstimate> {
    let point = |(_, probe): &(usize, &Probe)| probe.kind == ProbeKind::Point;
    probes
        .par_iter()
        .enumerate()
        .filter(point)
        .map(|(i, probe)| read(world, probe, i as u64, samples, options, progress))
        .collect()
}

/// Paths between two reports of progress.
pub const REPORT: usize = 4096;

fn read(
    world: &World,
    probe: &Probe,
    index: u64,
    samples: usize,
    options: &TraceOptions,
    progress: &(dyn Fn(u64) + Sync),
) -> ProbeEstimate {
    let report = |s: usize| {
        if (s + 1).is_multiple_of(REPORT) || s + 1 == samples {
            progress((s % REPORT + 1) as u64);
        }
    };
    let (p, n) = (probe.position, probe.normal);
    let delta = standoff(&world.mesh);
    // The patch under the probe, when it lies on a surface facing the same way.
    let under = world.under(p, n);
    let ignore = under.map_or(NO_FACE, |i| world.mesh.patches[i].face);
    let mut rays = 0;
    let mut rng = Rng::stream(options.seed, 2 * index);
    let mut luminance = Tally::default();
    for s in (0..samples).take_while(|_| !crate::interrupt::asked()) {
        let l = match under {
            Some(_) => luminance_along(world, Start::eye(p + n * delta, -n), &mut rng, options, &mut rays),
            None => luminance_along(world, Start::eye(p, n), &mut rng, options, &mut rays),
        };
        luminance.add(l);
        report(s);
    }
    let frame = Frame::around(n);
    let direct = world.luminaires.illuminance(&world.visibility, p, n, ignore);
    let mut rng = Rng::stream(options.seed, 2 * index + 1);
    let mut illuminance = Tally::default();
    for s in (0..samples).take_while(|_| !crate::interrupt::asked()) {
        let mut e = direct;
        if let Some(light) = world.emitters.sample_towards(&world.mesh, p, rng.uniform3()) {
            let cos = n.dot(light.direction);
            if cos > 0.0 && world.visibility.visible(p, light.point, [ignore, light.face]) {
                e += light.luminance * cos / light.pdf * power_heuristic(light.pdf, cos * FRAC_1_PI);
            }
        }
        if !world.openings.is_empty() {
            e += through_openings(world, p, n, ignore, rng.uniform3(), &mut rays);
        }
        let local = cosine_direction(rng.uniform(), rng.uniform());
        let d = frame.world(local);
        let start = Start { origin: p, direction: d, ignore, drawn: Some(local.z * FRAC_1_PI), camera: false };
        e += PI * luminance_along(world, start, &mut rng, options, &mut rays);
        illuminance.add(e);
        report(s);
    }
    let n = samples as u64;
    ProbeEstimate {
        name: probe.name.clone(),
        luminance: luminance.mean_and_error(n),
        illuminance: illuminance.mean_and_error(n),
    }
}

/// Next-event estimation of the sky through the openings on a receiver at `p` facing `n`
/// (on face `ignore`), weighted against the cosine-distributed directions, lx.
fn through_openings(world: &World, p: DVec3, n: DVec3, ignore: u32, u: [f64; 3], rays: &mut u64) -> f64 {
    let Some(light) = world.openings.sample_towards(p, u) else { return 0.0 };
    let cos = n.dot(light.direction);
    if cos <= 0.0 || light.luminance <= 0.0 {
        return 0.0;
    }
    *rays += 1;
    match Openings::clear(&world.visibility, p, light.direction, ignore) {
        true => light.luminance * cos / light.pdf * power_heuristic(light.pdf, cos * FRAC_1_PI),
        false => 0.0,
    }
}
