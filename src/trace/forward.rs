//! Forward ray tracing (`docs/design.md` §4): Monte Carlo light tracing from the emitters into
//! the `(patch, direction cell)` bins, a view-independent estimate of the discrete field.
//!
//! Photons leave the emitters chosen by flux, each carrying `Φ/P` lm, from a uniform
//! point in a cosine-distributed direction (luminaires: `luminaires.rs`, the sky and the sun
//! through the openings: `daylight_photons.rs`, weighted). At every surface a photon first counts as
//! incident flux of the patch it meets (illuminance `E_i = Φ_in/A_i`), then scatters into
//! a direction sampled from the continuous material (the same sampler as the backward
//! estimator: the models are reciprocal) and deposits its outgoing flux `w'` into the bin
//! of the patch it leaves (the twin, for light transmitted through a two-sided surface)
//! and of the cell holding its new direction. The outgoing flux of patch `i` in cell `k`
//! is `A_i μ_k L̄(i,k)` (`energy.rs`), so
//!
//! `L̂(i,k) = L0(i) + Σ deposits / (A_i μ_k)`,
//!
//! the area and projected-solid-angle average of the continuous field over the patch and
//! the cell: what `L(i,k)` of the linear system approximates. The emission is added
//! exactly. Russian roulette keeps a photon with probability `min(w'/w, 0.95)` after its
//! deposit. Standard errors come from the per-photon sums (each photon is one independent
//! sample of every bin); photons run in fixed chunks, chunks in parallel, and chunk sums
//! are added in chunk order, so the result depends only on the seed and the count.

use super::backward::{LONGEST_PATH, TraceOptions};
use super::emitters::Departure;
use super::statistics::Tally;
use super::world::World;
use crate::directions::DirectionSet;
use crate::geometry::NO_TWIN;
use crate::random::Rng;
use rayon::prelude::*;
use std::time::Instant;

/// Photons per chunk (one independent unit of parallel work).
const CHUNK: u64 = 1 << 14;

/// The forward estimate of the discrete field and of the patch illuminances.
#[derive(Debug, Clone, PartialEq)]
pub struct FieldEstimate {
    /// `L̂(i,k)` at `i·K + k`, cd/m².
    pub luminance: Vec<f64>,
    /// Its standard error, cd/m².
    pub luminance_error: Vec<f64>,
    /// Incident illuminance of every patch, lx.
    pub illuminance: Vec<f64>,
    /// Its standard error, lx.
    pub illuminance_error: Vec<f64>,
    /// Total flux leaving the surfaces other than by emission (reflected and transmitted),
    /// lm, and its standard error: one number whose error includes every correlation
    /// between the bins (a photon deposits into many).
    pub scattered: (f64, f64),
    /// Photons traced.
    pub photons: u64,
    /// Rays cast.
    pub rays: u64,
    /// Wall time, s.
    pub seconds: f64,
}

/// Traces `photons` photons; `progress(n)` after every chunk of `n` photons. A signal's
/// stop ends it after the chunks under way (`crate::interrupt`: the caller checks).
pub fn trace_photons(
    world: &World,
    directions: &DirectionSet,
    photons: u64,
    options: &TraceOptions,
    progress: &(dyn Fn(u64) + Sync),
) -> FieldEstimate {
    let start = Instant::now();
    let mesh = &world.mesh;
    let (n, k) = (mesh.len(), directions.len());
    let bins = n * k + n + 1;
    let share = world.photon_flux() / photons.max(1) as f64;
    let chunks = photons.div_ceil(CHUNK);
    let wave = (2 * rayon::current_num_threads()) as u64;
    let mut tallies = vec![Tally::default(); bins];
    let mut rays = 0;
    for first in (0..chunks).step_by(wave as usize).take_while(|_| !crate::interrupt::asked()) {
        let results: Vec<(Vec<Tally>, u64)> = (first..(first + wave).min(chunks))
            .into_par_iter()
            .map(|c| {
                let range = c * CHUNK..((c + 1) * CHUNK).min(photons);
                let count = range.end - range.start;
                let out = chunk(world, directions, range, share, options);
                progress(count);
                out
            })
            .collect();
        for (chunk_tallies, chunk_rays) in results {
            for (t, c) in tallies.iter_mut().zip(&chunk_tallies) {
                t.sum += c.sum;
                t.squares += c.squares;
            }
            rays += chunk_rays;
        }
    }
    let cells = directions.cells();
    let mut luminance = vec![0.0; n * k];
    let mut luminance_error = vec![0.0; n * k];
    for (i, p) in mesh.patches.iter().enumerate() {
        for (c, cell) in cells.iter().enumerate() {
            let (flux, error) = tallies[i * k + c].total_and_error(photons);
            luminance[i * k + c] = mesh.emission[i] + p.per_exposed_area(flux) / cell.projected;
            luminance_error[i * k + c] = p.per_exposed_area(error) / cell.projected;
        }
    }
    let (illuminance, illuminance_error) = mesh
        .patches
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let (flux, error) = tallies[n * k + i].total_and_error(photons);
            (p.per_exposed_area(flux), p.per_exposed_area(error))
        })
        .unzip();
    FieldEstimate {
        luminance,
        luminance_error,
        illuminance,
        illuminance_error,
        scattered: tallies[n * k + n].total_and_error(photons),
        photons,
        rays,
        seconds: start.elapsed().as_secs_f64(),
    }
}

/// The tallies of the photons `range` (each photon's deposits summed per bin first; the
/// last tally is the sum of its outgoing deposits).
fn chunk(
    world: &World,
    directions: &DirectionSet,
    range: std::ops::Range<u64>,
    share: f64,
    options: &TraceOptions,
) -> (Vec<Tally>, u64) {
    let (n, k) = (world.mesh.len(), directions.len());
    let mut tallies = vec![Tally::default(); n * k + n + 1];
    let mut deposits: Vec<(usize, f64)> = Vec::new();
    let mut rays = 0;
    for photon in range {
        deposits.clear();
        let mut rng = Rng::stream(options.seed, photon);
        follow(world, directions, share, options, &mut rng, &mut deposits, &mut rays);
        tallies[n * k + n].add(deposits.iter().filter(|&&(bin, _)| bin < n * k).map(|&(_, v)| v).sum());
        deposits.sort_unstable_by_key(|&(bin, _)| bin);
        let mut i = 0;
        while i < deposits.len() {
            let (bin, mut value) = deposits[i];
            i += 1;
            while i < deposits.len() && deposits[i].0 == bin {
                value += deposits[i].1;
                i += 1;
            }
            tallies[bin].add(value);
        }
    }
    (tallies, rays)
}

/// One photon's life: its deposits as `(bin, lm)`, bins `i·K + k` for outgoing flux and
/// `N·K + i` for incident flux.
fn follow(
    world: &World,
    directions: &DirectionSet,
    share: f64,
    options: &TraceOptions,
    rng: &mut Rng,
    deposits: &mut Vec<(usize, f64)>,
    rays: &mut u64,
) {
    let mesh = &world.mesh;
    let (n, k) = (mesh.len(), directions.len());
    let u = [rng.uniform(), rng.uniform(), rng.uniform(), rng.uniform(), rng.uniform()];
    let Some((departure, weight)) = depart(world, u) else { return };
    let (mut origin, mut direction, mut ignore) = (departure.origin, departure.direction, departure.face);
    let mut flux = share * weight;
    let last = options.max_order.unwrap_or(LONGEST_PATH).min(LONGEST_PATH);
    for order in 0..last {
        *rays += 1;
        let Some(hit) = world.landing(origin, direction, ignore) else { return };
        deposits.push((n * k + hit.patch, flux));
        let patch = &mesh.patches[hit.patch];
        let frame = patch.frame();
        let Some(s) = world.material(hit.patch).sample(frame.local(-direction), rng.uniform3()) else {
            return;
        };
        let outgoing = flux * s.weight;
        direction = frame.world(s.direction);
        let leaving = if s.direction.z >= 0.0 || patch.twin == NO_TWIN { hit.patch } else { patch.twin as usize };
        let cell = directions.lookup(mesh.patches[leaving].frame().local(direction));
        deposits.push((leaving * k + cell, outgoing));
        let survive = if order + 1 >= last { 0.0 } else { s.weight.min(0.95) };
        if outgoing <= 0.0 || !outgoing.is_finite() || rng.uniform() >= survive {
            return;
        }
        flux = outgoing / survive;
        origin = hit.point;
        ignore = patch.face;
    }
}

/// A photon's departure and weight: `u[0]` picks the emitting surfaces, the luminaires or
/// the daylight through the openings by their flux, the rest place it.
fn depart(world: &World, mut u: [f64; 5]) -> Option<(Departure, f64)> {
    let fluxes = [world.emitters.flux(), world.luminaires.flux(), world.daylight.flux()];
    let total: f64 = fluxes.iter().sum();
    let mut start = 0.0;
    for (group, flux) in fluxes.iter().enumerate() {
        let share = flux / total;
        let last = fluxes[group + 1..].iter().all(|&f| f <= 0.0);
        if share > 0.0 && (u[0] < start + share || last) {
            u[0] = ((u[0] - start) / share).clamp(0.0, 1.0 - f64::EPSILON);
            return match group {
                0 => world.emitters.emit(&world.mesh, u).map(|d| (d, 1.0)),
                1 => world.luminaires.emit(u),
                _ => world.daylight.emit(&world.visibility, u),
            };
        }
        start += share;
    }
    None
}
