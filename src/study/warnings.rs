//! Physics warnings of a solved case (issue 18, item 4): the field is computed, but the
//! scene probably is not what was meant. Each check looks at the solved model with rays:
//!
//! * light lost on the back of one-sided surfaces: the flux leaving every patch (its
//!   solved outgoing flux, sent in cosine-distributed directions) and every point luminaire
//!   (by its intensity) is followed to the first surface; what meets a back side is lost
//!   (a one-sided surface absorbs there), which in a room means a surface facing the wrong
//!   way. Warned above 2 % of the emitted flux, naming the three surfaces whose backs
//!   receive most. A ray starts from the patch's centroid, or where that lies inside a
//!   solid (a patch partly under furniture) from the first of its stratified points outside;
//!   a patch with none sends no ray;
//! * a `[[window]]` whose light lands on no surface (no surface sees its opening);
//! * a luminaire whose light never reaches a front side, or mostly meets backs (inside a
//!   box, above a ceiling);
//! * a probe or grid whose normal points into the surface it lies on, or which sees mostly
//!   the backs of surfaces (it lies behind one);
//! * negative escaped flux: not light but discretization error. The luminaires' direct
//!   light landing on the patches beyond their flux (its integration's error) is stated
//!   apart; the rest is the kernel's, exactly `Σ Φ_j (1 − s_j)` over the columns of `G`
//!   (`kernel::sent_shares`: the
//!   share of what a patch sends that the others receive, 1 in a closed scene); the
//!   columns' range and their deviation from 1 weighted by the solved outgoing flux are
//!   stated: the bound of the balance's discretization error;
//! * light escaping through a small opening (`openings.rs`): a missing wall or a gap;
//! * a probe closer to a patch than `near::NEAR` of the patch's size (`near.rs`): it
//!   reads the patch's mean where it sees mostly its nearest part;
//! * a grid facing away from every source, or with points left out of its statistics
//!   (inside a solid, under a surface nearer than its spacing: `grid_points.rs`);
//! * parallel light (the sun) and a glazed window: the glass's `τ(θ)` and the window's
//!   maintenance factor apply to the sky and ground it lets in, not to the beam;
//! * a mirror reflected cell to cell, not by images (`mirror_cells.rs`): its image smeared.
//!
//! The ones the model alone shows ([`before_solve`]: luminaires, probes, grids, parallel
//! light through glass) are what `--strict` refuses before solving.
//!
//! The rays are stratified with fixed seeds: the same case gives the same warnings.

use crate::geometry::Frame;
use crate::geometry::cosine_direction;
use crate::io::{NegativeEscape, SensorFault, Warning};
use crate::kernel::{closure_shares, sent_shares};
use crate::luminaire::Light;
use crate::model::{Model, place};
use crate::random::Rng;
use crate::readout::energy::EnergyBalance;
use crate::scene::Scene;
use crate::transfer::exposure::Backs;
use crate::transfer::occlusion::polygon_points;
use crate::visibility::NO_FACE;
use glam::DVec3;

/// Rays followed from the surfaces' outgoing flux.
const SURFACE_RAYS: usize = 20_000;
/// Rays per luminaire, per probe and per grid point.
const LUMINAIRE_RAYS: usize = 2_000;
const SENSOR_RAYS: usize = 256;
/// Share of the emitted flux lost on backs above which it is reported.
const BACKS: f64 = 0.02;

/// The warnings the model of `scene` shows before any solve: luminaires inside or behind
/// surfaces, probes and grids not in the room, probes near
/// patches, grids facing away from every source or with points left out (inside a solid,
/// under a surface: `--strict` refuses them before solving).
pub fn before_solve(scene: &Scene, model: &Model) -> Vec<Warning> {
    let mut out = Vec::new();
    luminaires(scene, model, &mut out);
    dark_windows(model, &mut out);
    sensors(scene, model, &mut out);
    out.extend(super::grid_points::facing_away(scene, model));
    out.extend(super::grid_points::left_out(scene, model));
    super::near::near_patches(scene, model, &mut out);
    out
}

/// Every warning of the solved field `x` of `model` (of `scene`), with its energy balance.
pub fn physics_warnings(scene: &Scene, model: &Model, x: &[f64], energy: &EnergyBalance) -> Vec<Warning> {
    let mut out = Vec::new();
    backs(scene, model, x, energy, &mut out);
    out.extend(before_solve(scene, model));
    out.extend(super::mirror_cells::mirrors_by_cells(scene, model));
    let shares = || {
        let areas: Vec<f64> = model.mesh.patches.iter().map(|p| p.exposed).collect();
        sent_shares(&model.kernel, &areas, &model.mirrors)
    };
    if energy.escaped < -1e-9 * energy.emitted.abs() {
        out.push(Warning::NegativeEscape(negative_escape(scene, model, x, energy, &shares())));
    } else if energy.escaped > super::openings::LOST * energy.emitted {
        let sent = shares();
        let closures = closure_shares(&model.kernel, &sent, !model.mirrors.is_empty());
        out.extend(super::openings::small_opening(scene, model, x, energy, &closures));
        out.extend(super::openings::kernel_loss(model, x, energy, &sent, &closures));
    }
    out
}

/// The negative escaped flux of a closed scene explained, and bounded by the kernel's
/// reciprocity error: the columns' sent shares `s` (`kernel::sent_shares`) against 1,
/// weighted by the solved outgoing flux (the escaped flux is exactly `Σ Φ (1 − s)` plus
/// the luminaires' light that lands nowhere).
fn negative_escape(scene: &Scene, model: &Model, x: &[f64], energy: &EnergyBalance, shares: &[f64]) -> NegativeEscape {
    let (e, k) = (energy, model.kernel.cells());
    let flux = super::openings::outgoing(model, x);
    let over: f64 = (0..shares.len()).map(|c| flux(c) * (shares[c] - 1.0).max(0.0)).sum();
    let either: f64 = (0..shares.len()).map(|c| flux(c) * (shares[c] - 1.0).abs()).sum();
    let sending: Vec<usize> = (0..shares.len()).filter(|&c| flux(c) > 0.0).collect();
    let (low, high) =
        sending.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), &c| (l.min(shares[c]), h.max(shares[c])));
    let error = |c: usize| flux(c) * (shares[c] - 1.0).abs();
    let worst = sending.iter().copied().max_by(|&a, &b| error(a).total_cmp(&error(b)));
    let worst = worst.map(|c| (shares[c], place(scene, &model.mesh, c, k)));
    // the luminaires' part: their light landing on the patches beyond their flux
    let landed: f64 = model.direct.intercepted.iter().sum();
    let beyond = landed - e.luminaire_emitted.iter().sum::<f64>();
    let luminaires = (beyond > 1e-9 * e.emitted).then_some(beyond);
    NegativeEscape { escaped: e.escaped, emitted: e.emitted, luminaires, low, high, worst, over, either }
}

/// Every `[[window]]` none of whose light lands on a surface: no surface sees its opening
/// (it lies behind the room's surfaces), so it lets in nothing.
fn dark_windows(model: &Model, out: &mut Vec<Warning>) {
    for (source, landed) in model.sources.iter().zip(&model.direct.intercepted) {
        if matches!(source.light, Light::Window { .. }) && *landed <= 0.0 {
            out.push(Warning::WindowDark { window: source.name.clone() });
        }
    }
}

/// The first surface along `direction` from `origin`: `Some(Some(surface))` for the back
/// of a one-sided surface, `Some(None)` for a front, `None` for nothing.
fn back_hit(model: &Model, origin: DVec3, direction: DVec3, ignore: u32) -> Option<Option<usize>> {
    let hit = model.faces.landing(&model.mesh, &model.visibility, origin, direction, ignore)?;
    Some(match hit.facing {
        Some(_) => None,
        None => Some(model.mesh.patches[model.faces.first(hit.face)].surface as usize),
    })
}

fn backs(scene: &Scene, model: &Model, x: &[f64], energy: &EnergyBalance, out: &mut Vec<Warning>) {
    let (mesh, k) = (&model.mesh, model.kernel.cells());
    let cells = model.kernel.directions.cells();
    let outgoing: Vec<f64> = mesh
        .patches
        .iter()
        .enumerate()
        .map(|(i, p)| p.exposed * (0..k).map(|c| x[i * k + c] * cells[c].projected).sum::<f64>())
        .collect();
    let total: f64 = outgoing.iter().sum();
    let mut lost = vec![0.0; scene.surfaces.len()];
    if total > 0.0 {
        let mut rng = Rng::keyed(4);
        let solids = Backs::of(mesh);
        let mut cdf = Vec::with_capacity(outgoing.len());
        let mut running = 0.0;
        for f in &outgoing {
            running += f;
            cdf.push(running);
        }
        for _ in 0..SURFACE_RAYS {
            let i = cdf.partition_point(|&c| c < rng.uniform() * total).min(cdf.len() - 1);
            let p = &mesh.patches[i];
            // from the exposed part: a point inside a solid (a patch partly under furniture)
            // sends nothing, and its rays would meet the solid's inside
            let outside = |x: &DVec3| solids.outside(&model.visibility, p, *x);
            let Some(origin) = std::iter::once(p.centroid).chain(polygon_points(&p.polygon)).find(outside) else {
                continue;
            };
            let direction = p.frame().world(cosine_direction(rng.uniform(), rng.uniform()));
            if let Some(Some(surface)) = back_hit(model, origin, direction, p.face) {
                lost[surface] += total / SURFACE_RAYS as f64;
            }
        }
    }
    for (source, flux) in model.sources.iter().zip(&energy.luminaire_emitted) {
        if let Light::Point { position, .. } = source.light {
            for (direction, weight) in photons(source, *flux) {
                if let Some(Some(surface)) = back_hit(model, position, direction, NO_FACE) {
                    lost[surface] += weight;
                }
            }
        }
    }
    let sum: f64 = lost.iter().sum();
    if sum <= BACKS * energy.emitted {
        return;
    }
    let mut order: Vec<usize> = (0..lost.len()).filter(|&i| lost[i] > 0.0).collect();
    order.sort_by(|&a, &b| lost[b].total_cmp(&lost[a]));
    let surfaces = order.iter().take(3).map(|&i| (scene.surfaces[i].name.clone(), lost[i])).collect();
    out.push(Warning::BacksLost { lost: sum, emitted: energy.emitted, surfaces });
}

/// Stratified directions of a point luminaire with the flux each carries.
fn photons(source: &crate::luminaire::Source, flux: f64) -> Vec<(DVec3, f64)> {
    let n = (LUMINAIRE_RAYS as f64).sqrt() as usize;
    let mut rng = Rng::keyed(7);
    let mut out = Vec::with_capacity(n * n);
    for a in 0..n {
        for b in 0..n {
            let z = 1.0 - 2.0 * (a as f64 + rng.uniform()) / n as f64;
            let phi = std::f64::consts::TAU * (b as f64 + rng.uniform()) / n as f64;
            let r = (1.0 - z * z).max(0.0).sqrt();
            let d = DVec3::new(r * phi.cos(), r * phi.sin(), z);
            out.push((d, source.intensity(d)));
        }
    }
    let sum: f64 = out.iter().map(|(_, w)| w).sum();
    if sum > 0.0 {
        out.iter_mut().for_each(|(_, w)| *w *= flux / sum);
    }
    out
}

fn luminaires(scene: &Scene, model: &Model, out: &mut Vec<Warning>) {
    for (l, source) in scene.luminaires.iter().zip(&model.sources) {
        let Light::Point { position, .. } = source.light else { continue };
        let (mut front, mut back, mut total) = (0.0, 0.0, 0.0);
        for (direction, w) in photons(source, 1.0) {
            total += w;
            match back_hit(model, position, direction, NO_FACE) {
                Some(None) => front += w,
                Some(Some(_)) => back += w,
                None => {}
            }
        }
        if total <= 0.0 {
            continue;
        }
        let (luminaire, backs) = (l.name.clone(), 100.0 * back / total);
        if front == 0.0 {
            out.push(Warning::LuminaireUnseen { luminaire, backs });
        } else if back > 0.5 * total {
            out.push(Warning::LuminaireMostlyBacks { luminaire, backs });
        }
    }
}

/// What a sensor at `p` facing `n` finds wrong, if anything.
fn sensor(scene: &Scene, model: &Model, p: DVec3, n: DVec3) -> Option<SensorFault> {
    let (mesh, vis) = (&model.mesh, &model.visibility);
    let name = |i: usize| scene.surfaces[i].name.clone();
    if model.faces.under(mesh, vis, p, n).is_none()
        && let Some(i) = model.faces.under(mesh, vis, p, -n)
    {
        return Some(SensorFault::IntoSurface { surface: name(mesh.patches[i].surface as usize) });
    }
    let frame = Frame::around(n);
    let origin = p + n * 1e-6 * mesh.extent();
    let mut rng = Rng::keyed(11);
    let (mut backs, mut surface) = (0usize, 0);
    for _ in 0..SENSOR_RAYS {
        let d = frame.world(cosine_direction(rng.uniform(), rng.uniform()));
        if let Some(Some(s)) = back_hit(model, origin, d, NO_FACE) {
            backs += 1;
            surface = s;
        }
    }
    (backs * 2 > SENSOR_RAYS)
        .then(|| SensorFault::Behind { backs: 100.0 * backs as f64 / SENSOR_RAYS as f64, surface: name(surface) })
}

fn sensors(scene: &Scene, model: &Model, out: &mut Vec<Warning>) {
    for p in &scene.probes {
        if let Some(fault) = sensor(scene, model, p.position, p.normal) {
            out.push(Warning::Probe { probe: p.name.clone(), fault });
        }
    }
    for g in &scene.grids {
        let points = g.points();
        let mut bad: Vec<SensorFault> = points.iter().filter_map(|&q| sensor(scene, model, q, g.normal)).collect();
        if bad.len() * 2 > points.len() {
            let faulty = bad.len();
            out.push(Warning::Grid { grid: g.name.clone(), faulty, points: points.len(), first: bad.swap_remove(0) });
        }
    }
}
