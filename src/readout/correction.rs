//! A reading's correction near geometry (`docs/design.md` §5, "The reading near
//! geometry", (5.4)): the gather of `gather.rs` reads every surface at its patch's (or leaf's)
//! mean luminance, which is wrong where the patch is large against its distance from the
//! point: a probe 1 cm from the foot of a block reads the floor's 3 cm patch at its mean,
//! though the floor darkens towards the foot.
//!
//! Every Lambertian patch `j` that the point sees closer than [`NEAR`] times the patch's
//! diameter is cut along its shadow edges as the gather cuts it
//! (`transfer::occlusion::cut_along_shadows`), and each piece into quarters while it lies
//! closer than [`NEAR`] times its own diameter (down to [`NEAR_DEPTH`] levels); each final
//! piece `a` reads the luminance of its centroid `c_a` gathered there from the field
//! (`luminance::gathered`: one bounce past the field) instead of the patch's value:
//!
//! `ΔI_d(p) = Σ_j Σ_a Σ_m F_{dA(p)→a}^{d,m} V_a (L_j(c_a → p) − L_j(m))`,
//!
//! added to the gathered `I_d(p)`. A near patch whose unoccluded light at the point is below
//! [`NEGLIGIBLE`] of all the point receives is left out. Where the field is right and the patch small against its
//! distance, the pieces' luminances average to the patch's and `ΔI` vanishes; the farther
//! patches, read at their means, are left as they are.
//!
//! Each piece costs a gather over every patch (about 9 ms on the Cornell box's 3,400
//! leaves here before the clear hulls of `visibility/hull.rs`, growing with the patches): probes are corrected, grid points
//! (`grid.rs`, hundreds a plane, often a few centimetres above desks) are not. In a piece's
//! gather a patch of small light ([`PIECE_SAMPLED`]) is seen by one ray instead of four to
//! eight, as in the error bars' (`docs/accuracy.md`, "One ray in the pieces' gathers").

use crate::geometry::{ConvexPolygon, Frame, Patch};
use crate::model::Model;
use crate::readout::cut::Cut;
use crate::readout::field::Field;
use crate::readout::gather::{incident_at, sum};
use crate::readout::glossy::is_diffuse;
use crate::readout::lit::Lit;
use crate::readout::luminance::{RELIT_SHADOW_CUT, gathered_each};
use crate::transfer::contour::point_to_patch;
use crate::transfer::form_factor::{Binning, binned_point};
use crate::transfer::occlusion::cut_along_shadows;
use crate::visibility::{NO_BLOCKER, SightTo};
use glam::DVec3;
use rayon::prelude::*;
use std::cell::Cell;
use std::f64::consts::PI;

/// A patch (and then a piece of it) is near a point closer than this many times its
/// diameter.
pub const NEAR: f64 = 1.0;

/// A near patch is cut along shadow edges into pieces no smaller than its area over this.
pub const SHADOW_PIECES: f64 = 16.0;

/// Most levels of cutting a near piece into quarters.
pub const NEAR_DEPTH: u32 = 4;

/// How a piece's gather cuts the patches it sees along shadow edges
/// ([`RELIT_SHADOW_CUT`]), and below which light a patch is seen by one ray to one of
/// its points ([`PIECE_SAMPLED`]).
pub const PIECE_CUT: Cut<'static> = Cut { fraction: RELIT_SHADOW_CUT, by: &[], sampled: PIECE_SAMPLED };

/// In a piece's gather, a patch whose light unoccluded is below this fraction of all the
/// piece's point would receive unoccluded is seen by one ray to one of its stratified
/// points picked by a hash of the point and the patch (`Cut::sampled`): unbiased.
pub const PIECE_SAMPLED: f64 = 1e-4;

/// A near patch whose unoccluded light at the point is below this fraction of all the light
/// the point receives is not corrected: its correction could move the reading by about as
/// much at most.
pub const NEGLIGIBLE: f64 = 1e-3;

/// The light arriving at a receiver at a point, per cell of its frame, corrected near
/// geometry.
#[derive(Debug, Clone, PartialEq)]
pub struct Corrected {
    /// The patch the point lies on, if any.
    pub patch: Option<usize>,
    /// `I_d + ΔI_d` (each at least 0): gathered from the surfaces and corrected.
    pub incident: Vec<f64>,
    /// `D_d`: directly from the luminaires.
    pub direct: Vec<f64>,
    /// The correction's illuminance `π Σ_d` (change of `I_d`), lx.
    pub correction: f64,
}

impl Corrected {
    /// `(E, E_direct)`: the illuminance `π Σ_d (I_d + ΔI_d + D_d)` and its direct part, lx.
    pub fn illuminance(&self) -> (f64, f64) {
        let direct = PI * self.direct.iter().sum::<f64>();
        (PI * self.incident.iter().sum::<f64>() + direct, direct)
    }
}

/// The light arriving at a receiver at `p` facing the unit `n`, gathered (`gather.rs`) and
/// corrected near geometry, the pieces' gathers cut by [`PIECE_CUT`].
pub fn corrected(model: &Model, field: &Field, p: DVec3, n: DVec3) -> Corrected {
    corrected_with(model, field, p, n, &PIECE_CUT)
}

/// [`corrected`], the pieces' gathers cut by `pieces` (`cut.rs`; only its fraction and
/// `sampled` count: the field read is the one rule).
pub fn corrected_with(model: &Model, field: &Field, p: DVec3, n: DVec3, pieces: &Cut) -> Corrected {
    let (at, mut incident, direct) = incident_at(model, field, p, n, &[]);
    let before = PI * incident.iter().sum::<f64>();
    let total = incident.iter().chain(&direct).sum::<f64>();
    let delta = near_correction(model, field, p, &at.frame, at.ignore, total, pieces);
    incident.iter_mut().zip(&delta).for_each(|(i, d)| *i = (*i + d).max(0.0));
    let correction = PI * incident.iter().sum::<f64>() - before;
    Corrected { patch: at.patch, incident, direct, correction }
}

/// `ΔI_d(p)` per cell of `frame` at `p` (ignoring face `ignore`), in the units of `I_d`;
/// `total` is all the light the point receives, `Σ_d (I_d + D_d)`; the pieces' gathers cut
/// by `pieces`.
pub fn near_correction(
    model: &Model,
    field: &Field,
    p: DVec3,
    frame: &Frame,
    ignore: u32,
    total: f64,
    pieces: &Cut,
) -> Vec<f64> {
    let cells = model.kernel.directions.len();
    let binning = Binning::new(&model.kernel.directions);
    let patches = &model.mesh.patches;
    let lit = [Lit::own(model, field)];
    let piece_cut = Cut { by: &[], ..*pieces };
    let near: Vec<usize> = (0..patches.len())
        .filter(|&j| {
            let s = &patches[j];
            s.face != ignore
                && is_diffuse(&model.materials[s.material as usize])
                && s.polygon.distance_to(p) < NEAR * s.polygon.diameter()
                && point_to_patch(p, frame.normal, s) * field.brightest(j) > NEGLIGIBLE * total
        })
        .collect();
    near.par_iter()
        .fold(
            || (vec![0.0; cells], Vec::new(), Cell::new(NO_BLOCKER)),
            |(mut sum, mut bins, blocker), &j| {
                let s = &patches[j];
                let sight = SightTo::new(&model.visibility, p, [ignore, s.face], &blocker);
                let worth = |piece: &ConvexPolygon| piece.area() > s.area / SHADOW_PIECES;
                cut_along_shadows(&s.polygon, 0, &sight, &worth, &mut |piece, seen| {
                    piece.pieces_within(p, 1.0 / NEAR, NEAR_DEPTH, &mut |a| {
                        bins.clear();
                        binned_point(p, frame, &Patch { polygon: *a, ..*s }, &binning, &mut bins);
                        let c = a.centroid();
                        let l = gathered_each(model, &lit, j, c, (p - c).normalize(), &piece_cut)[0];
                        for &(d, m, f) in bins.iter() {
                            sum[d as usize] += f * seen * (l - field.at(j, m as usize));
                        }
                    });
                });
                (sum, bins, blocker)
            },
        )
        .map(|(sum, _, _)| sum)
        .reduce(|| vec![0.0; cells], |a, b| sum(&a, &b))
}
