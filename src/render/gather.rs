//! The final gather: one more reflection evaluated at the hit point `q` itself,
//! `L(q, k) = Le + Σ_d ρ̄(k, d) I_d(q)` (`design.md` §5), from the solved field.
//!
//! The light arriving at `q` per cell `d`, `I_d = (1/π) ∫_d L cosθ dω`, is split in two:
//! * **direct**: every self-emitting patch `j` contributes `Le_j F^{d}_{q→P_j} V(q, P_j)`,
//!   the exact contour-integral factor split by cells and the visibility fraction of the
//!   kernel's four stratified points (`transfer::occlusion`): no noise from small lamps;
//!   every luminaire its exact light at `q` (`luminaire::arriving_at`, one shadow ray);
//! * **indirect**: `rays` cosine-distributed rays (Latin-hypercube stratified); each adds
//!   `(L_j(m) − Le_j)/rays` to the cell it leaves through, `L_j(m)` the stored luminance of
//!   the patch it hits in the cell pointing back at `q` (its emission was counted above).
//!
//! A transmitting two-sided surface also gathers on its back side. The patch pattern of
//! the solution then shows only through the light of the second reflection onward.

use super::solved::Solved;
use crate::geometry::{Frame, NO_TWIN};
use crate::luminaire::{OPENING_ETA, arriving_at};
use crate::material::Block;
use crate::random::Rng;
use crate::transfer::contour::point_to_patch;
use crate::transfer::form_factor::{Binning, binned_point};
use crate::transfer::occlusion::{POINTS, sample_points};
use glam::DVec3;
use std::cell::RefCell;
use std::f64::consts::TAU;

/// Binned point factors `(d, m, F)`, as `binned_point` pushes them.
type Bins = Vec<(u16, u16, f64)>;

thread_local! {
    /// Per-thread buffers: the incident light per cell and the binned factors.
    static SCRATCH: RefCell<(Vec<f64>, Bins)> = const { RefCell::new((Vec::new(), Vec::new())) };
}

/// The luminance leaving `patch` at `q` towards the unit direction `towards`, gathered.
pub fn final_gather(lit: &Solved, patch: usize, q: DVec3, towards: DVec3, rays: usize, rng: &mut Rng) -> f64 {
    let p = &lit.mesh.patches[patch];
    let k = lit.directions.lookup(p.frame().local(towards));
    let block = &lit.blocks[p.material as usize];
    SCRATCH.with_borrow_mut(|(incident, bins)| {
        gather_incident(lit, q, &p.frame(), p.face, rays, rng, incident, bins);
        let mut l = lit.mesh.emission[patch] + reflected(block, k, incident, Block::at);
        if block.transmits() && p.twin != NO_TWIN {
            let back = &lit.mesh.patches[p.twin as usize];
            gather_incident(lit, q, &back.frame(), back.face, rays, rng, incident, bins);
            l += reflected(block, k, incident, |b, k, d| b.transmit_at(k, d).unwrap_or(0.0));
        }
        l
    })
}

/// `Σ_d coefficient(k, d) I_d`.
fn reflected(block: &Block, k: usize, incident: &[f64], coefficient: impl Fn(&Block, usize, usize) -> f64) -> f64 {
    incident.iter().enumerate().map(|(d, i)| coefficient(block, k, d) * i).sum()
}

/// `I_d(q)` for the cells of `frame` into `incident`, ignoring the face `face`.
#[allow(clippy::too_many_arguments)]
fn gather_incident(
    lit: &Solved,
    q: DVec3,
    frame: &Frame,
    face: u32,
    rays: usize,
    rng: &mut Rng,
    incident: &mut Vec<f64>,
    bins: &mut Bins,
) {
    incident.clear();
    incident.resize(lit.directions.len(), 0.0);
    let binning = Binning::new(&lit.directions);
    for &j in &lit.emitters {
        let s = &lit.mesh.patches[j as usize];
        if s.face == face || point_to_patch(q, frame.normal, s) <= 0.0 {
            continue;
        }
        let seen = sample_points(s).iter().filter(|&&y| lit.visibility.visible(q, y, [face, s.face])).count();
        if seen == 0 {
            continue;
        }
        let weight = seen as f64 / POINTS as f64 * lit.mesh.emission[j as usize];
        bins.clear();
        binned_point(q, frame, s, &binning, bins);
        for &(d, _, f) in bins.iter() {
            incident[d as usize] += weight * f;
        }
    }
    let luminaires = arriving_at(&lit.sources, &lit.visibility, &lit.directions, q, frame, face, OPENING_ETA);
    incident.iter_mut().zip(luminaires).for_each(|(i, d)| *i += d);
    let shift = rng.next_u64() as usize % rays.max(1);
    let stride = if rays.is_multiple_of(7) { 1 } else { 7 };
    for r in 0..rays {
        let u = (r as f64 + rng.uniform()) / rays as f64;
        let v = (((r * stride + shift) % rays) as f64 + rng.uniform()) / rays as f64;
        let (radius, phi) = (u.sqrt(), TAU * v);
        let local = DVec3::new(radius * phi.cos(), radius * phi.sin(), (1.0 - u).max(0.0).sqrt());
        let w = frame.world(local);
        if let Some((j, _)) = lit.hit_ignoring(q, w, face) {
            let d = lit.directions.lookup(local);
            incident[d] += (lit.flat(j, -w) - lit.mesh.emission[j]) / rays as f64;
        }
    }
}
