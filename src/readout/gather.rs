//! The light arriving at an exact point, gathered from the solved field (`docs/design.md` §5):
//! the illuminance on a receiver, and the light a surface point reflects
//! (`luminance.rs`).
//!
//! The light arriving at `p` is gathered per direction cell `d` of a frame at `p`:
//! `I_d(p) = Σ_j Σ_m L_j(m) F_{dA(p)→P_j}^{d,m} V(p, P_j)` (the exact contour-integral form
//! factor, split by cells as in the kernel, and a visibility fraction from rays to
//! stratified points of `P_j`; a patch whose points and corners disagree lies on a shadow
//! edge and is cut into quarters (`transfer::occlusion::cut_along_shadows`), each piece
//! weighed by its own rays, while the light the piece would send unoccluded exceeds
//! [`SHADOW_CUT`] of all the point would receive unoccluded; where the cut allows it, patches
//! of small light by one ray, alone or in runs: `runs.rs`). A Phong or GGX patch's light
//! towards `p` is, piece by piece, its final gather at the piece's centroid towards `p`
//! (`glossy.rs`, [`PIECE_RAYS`] directions) instead of its cell value `L_j(m)`, each shadow
//! piece cut further while it spans more than [`LOBE_PIECE`] times the lobe's half width
//! seen from `p`. A plane
//! mirror's light is not its cell values but the images of the other patches seen through
//! it (`mirrored.rs`, `docs/mirrors.md`). The
//! luminaires' light arrives exactly at the point (`crate::luminaire::arriving_at`, one shadow ray each) as
//! `D_d(p)`; the illuminance is `E = π Σ_d (I_d + D_d)`, of which `π Σ_d D_d` is direct
//! from the luminaires.

use crate::geometry::{ConvexPolygon, Frame, Patch};
use crate::luminaire::arriving_at;
use crate::model::Model;
use crate::readout::cut::{Cut, Worth};
use crate::readout::field::Field;
use crate::readout::glossy::{ModelSurroundings, PIECE_RAYS};
use crate::readout::lit::Lit;
use crate::readout::mirrored::{on_mirrors, through_mirrors};
use crate::readout::runs::{pick, runs};
use crate::sky::READING;
use crate::transfer::contour::point_to_patch;
use crate::transfer::form_factor::{Binning, binned_point};
use crate::transfer::occlusion::{cut_along_shadows, sample_one};
use crate::visibility::{NO_BLOCKER, NO_FACE, SightTo};
use glam::DVec3;
use rayon::prelude::*;
use std::cell::Cell;
use std::f64::consts::PI;

/// Illuminance, lx, on a receiver at `p` facing the unit `n` (on a surface or in free
/// space), the luminaires' direct light included; not corrected near geometry (a grid
/// point's: `correction.rs` says why).
pub fn illuminance_at(model: &Model, field: &Field, p: DVec3, n: DVec3) -> f64 {
    illuminance_and_direct_at(model, field, p, n, &[]).0
}

/// [`illuminance_at`] and its part directly from the sources (luminaires, sun, openings), lx;
/// the pieces along shadow edges cut by the field's own rule, or by that of any field of
/// `by` (`cut.rs`: fields whose readings are summed).
pub fn illuminance_and_direct_at(model: &Model, field: &Field, p: DVec3, n: DVec3, by: &[&Field]) -> (f64, f64) {
    illuminance_and_direct_each(model, &[Lit::own(model, field)], p, n, by)[0]
}

/// [`illuminance_and_direct_at`] for each field of `lits` under its own light, the gather's
/// rays and factors shared (`lit.rs`), cut by the rules of `by` (of all of `lits` when it
/// names none).
pub fn illuminance_and_direct_each(model: &Model, lits: &[Lit], p: DVec3, n: DVec3, by: &[&Field]) -> Vec<(f64, f64)> {
    let (_, each) = incident_each(model, lits, p, n, by);
    let total = |cells: &[f64]| PI * cells.iter().sum::<f64>();
    each.iter().map(|(incident, direct)| (total(incident) + total(direct), total(direct))).collect()
}

/// A receiver at a point: the patch it lies on (if any), the frame its light is binned
/// in (the patch's, or one around the receiver's normal) and the face its rays ignore.
pub(crate) struct Receiver {
    pub patch: Option<usize>,
    pub frame: Frame,
    pub ignore: u32,
}

impl Receiver {
    /// The receiver at `p` facing the unit `n`.
    pub fn at(model: &Model, p: DVec3, n: DVec3) -> Receiver {
        let patch = model.faces.under(&model.mesh, &model.visibility, p, n);
        let frame = patch.map_or_else(|| Frame::around(n), |i| model.mesh.patches[i].frame());
        let ignore = patch.map_or(NO_FACE, |i| model.mesh.patches[i].face);
        Receiver { patch, frame, ignore }
    }
}

/// The receiver at `p` facing `n` and the light arriving there per cell of its frame:
/// gathered from the surfaces (cut by the rules of `by`, as [`illuminance_and_direct_at`]),
/// and directly from the luminaires.
pub(super) fn incident_at(
    model: &Model,
    field: &Field,
    p: DVec3,
    n: DVec3,
    by: &[&Field],
) -> (Receiver, Vec<f64>, Vec<f64>) {
    let (at, mut each) = incident_each(model, &[Lit::own(model, field)], p, n, by);
    let (incident, direct) = each.swap_remove(0);
    (at, incident, direct)
}

/// [`incident_at`] for each field of `lits` under its own light, the gather's rays and
/// factors shared (`lit.rs`): per field, what arrives from the surfaces and directly, per cell.
#[allow(clippy::type_complexity)]
fn incident_each(
    model: &Model,
    lits: &[Lit],
    p: DVec3,
    n: DVec3,
    by: &[&Field],
) -> (Receiver, Vec<(Vec<f64>, Vec<f64>)>) {
    let at = Receiver::at(model, p, n);
    let incident = per_cell_each(model, lits, p, &at.frame, at.ignore, &Cut { fraction: SHADOW_CUT, by, sampled: 0.0 });
    let direct = |lit: &Lit| {
        arriving_at(lit.sources, &model.visibility, &model.kernel.directions, p, &at.frame, at.ignore, READING)
    };
    let each = lits.iter().zip(incident).map(|(lit, e)| (e, direct(lit))).collect();
    (at, each)
}

/// All the light arriving at point `q` of patch `s` per cell of its frame: gathered from
/// the surfaces plus direct from the luminaires.
pub(super) fn arriving(model: &Model, field: &Field, q: DVec3, s: &Patch) -> Vec<f64> {
    arriving_within(model, field, q, s, &Cut::own(SHADOW_CUT))
}

/// [`arriving`], with the pieces along shadow edges cut by `cut` (as [`SHADOW_CUT`]).
pub(super) fn arriving_within(model: &Model, field: &Field, q: DVec3, s: &Patch, cut: &Cut) -> Vec<f64> {
    arriving_each(model, &[Lit::own(model, field)], q, s, cut).swap_remove(0)
}

/// [`arriving_within`] for each field of `lits` under its own light, the pieces' rays and
/// factors shared (`lit.rs`).
pub(super) fn arriving_each(model: &Model, lits: &[Lit], q: DVec3, s: &Patch, cut: &Cut) -> Vec<Vec<f64>> {
    let frame = s.frame();
    let gathered = per_cell_each(model, lits, q, &frame, s.face, cut);
    let direct =
        |lit: &Lit| arriving_at(lit.sources, &model.visibility, &model.kernel.directions, q, &frame, s.face, READING);
    lits.iter().zip(gathered).map(|(lit, g)| sum(&g, &direct(lit))).collect()
}

pub(super) fn sum(a: &[f64], b: &[f64]) -> Vec<f64> {
    a.iter().zip(b).map(|(x, y)| x + y).collect()
}

/// A piece of a patch crossed by a shadow edge is cut further only while the light it
/// would send to the point unoccluded exceeds this fraction of all the light the point
/// would receive unoccluded; below it, its visibility is the fraction of its four points
/// that see (`docs/hierarchy.md`, "Readouts", measures what this changes).
pub const SHADOW_CUT: f64 = 1e-4;

/// A piece of a Phong or GGX patch is cut into quarters while it spans, seen from the
/// gathering point, more than this many times its lobe's half width (`lobe_width`): the
/// light it sends towards the point follows the direction towards the point, which turns
/// by the piece's diameter over its distance from one side of it to the other.
pub const LOBE_PIECE: f64 = 2.0;

/// Most levels of cutting a glossy piece by [`LOBE_PIECE`].
pub const LOBE_DEPTH: u32 = 5;

/// `I_d(p)`: the light arriving at `p` per cell of `frame`, ignoring face `ignore`.
pub fn gather(model: &Model, field: &Field, p: DVec3, frame: &Frame, ignore: u32) -> Vec<f64> {
    per_cell(model, field, p, frame, ignore, &Cut::own(SHADOW_CUT))
}

fn per_cell(model: &Model, field: &Field, p: DVec3, frame: &Frame, ignore: u32, cut: &Cut) -> Vec<f64> {
    per_cell_each(model, &[Lit::own(model, field)], p, frame, ignore, cut).swap_remove(0)
}

/// `I_d(p)` of each field of `lits`, every piece's rays and factors found once and its light
/// weighed by each field; cut by the rule of `cut` (of all the fields of `lits` when it
/// names none).
fn per_cell_each(model: &Model, lits: &[Lit], p: DVec3, frame: &Frame, ignore: u32, cut: &Cut) -> Vec<Vec<f64>> {
    let cells = model.kernel.directions.len();
    let binning = Binning::new(&model.kernel.directions);
    let patches = &model.mesh.patches;
    let mirrored = on_mirrors(model);
    let geometric: Vec<f64> = patches
        .par_iter()
        .enumerate()
        .map(|(j, s)| match s.face == ignore || mirrored[j] {
            true => 0.0,
            false => point_to_patch(p, frame.normal, s).max(0.0),
        })
        .collect();
    let fields: Vec<&Field> = lits.iter().map(|l| l.field).collect();
    let rule = Cut { by: if cut.by.is_empty() { &fields } else { cut.by }, ..*cut };
    let worth = Worth::new(&rule, fields[0], &geometric, |j| j, 1.0);
    let surroundings: Vec<ModelSurroundings> = fields.iter().map(|f| ModelSurroundings::new(model, f)).collect();
    let lobe = |j: usize| model.materials[patches[j].material as usize].lobe_width();
    let runs = runs(patches, &worth, |j| lobe(j).is_some() || !worth.sampled(j));
    let surfaces = runs
        .par_iter()
        .fold(
            || (vec![0.0; lits.len() * cells], Vec::new(), Cell::new(NO_BLOCKER)),
            |(mut sum, mut bins, blocker), run| {
                // A run's hash is apart from its leaves' (`pick(p, j)`, `j` below the leaf count).
                let (j, weight) = run.pick(&worth, pick(p, patches.len() + run.start));
                let s = &patches[j];
                let sight = SightTo::new(&model.visibility, p, [ignore, s.face], &blocker);
                let one_ray = worth.sampled(j);
                let worth = |piece: &ConvexPolygon| worth.cuts(j, s.area, piece.area());
                let lobe = lobe(j);
                let mut visit = |piece: &ConvexPolygon, seen: f64| {
                    let seen = seen * weight;
                    let Some(width) = lobe else {
                        bins.clear();
                        binned_point(p, frame, &Patch { polygon: *piece, ..*s }, &binning, &mut bins);
                        for (field, sum) in fields.iter().zip(sum.chunks_mut(cells)) {
                            bins.iter().for_each(|&(d, m, f)| sum[d as usize] += f * seen * field.at(j, m as usize));
                        }
                        return;
                    };
                    piece.pieces_within(p, LOBE_PIECE * width, LOBE_DEPTH, &mut |a| {
                        bins.clear();
                        binned_point(p, frame, &Patch { polygon: *a, ..*s }, &binning, &mut bins);
                        let c = a.centroid();
                        for (around, sum) in surroundings.iter().zip(sum.chunks_mut(cells)) {
                            let towards_p = around.outgoing(j, c, (p - c).normalize(), PIECE_RAYS);
                            bins.iter().for_each(|&(d, _, f)| sum[d as usize] += f * seen * towards_p);
                        }
                    });
                };
                match one_ray {
                    true => sample_one(&s.polygon, &sight, pick(p, j), &mut visit),
                    false => cut_along_shadows(&s.polygon, 0, &sight, &worth, &mut visit),
                };
                (sum, bins, blocker)
            },
        )
        .map(|(sum, _, _)| sum)
        .reduce(|| vec![0.0; lits.len() * cells], |a, b| sum(&a, &b));
    let mirrors = |field: &Field| through_mirrors(model, field, p, frame, ignore, cut);
    surfaces.chunks(cells).zip(&fields).map(|(s, f)| sum(s, &mirrors(f))).collect()
}
