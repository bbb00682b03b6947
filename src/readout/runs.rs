//! Which leaves a gather's rays go to, when a leaf of small light is seen by one ray
//! (`Cut::sampled`: the error bars' gathers and the pieces' gathers of the correction near
//! geometry, `docs/design.md` (5.2), (5.4), (5.5)).
//!
//! A leaf that sends the point less than `Cut::sampled` of all it would receive unoccluded
//! is seen by one ray to one of its stratified points, picked by a hash of the point and the
//! leaf (`transfer::occlusion::sample_one`): an unbiased estimate of the fraction its points
//! see. Such leaves come in runs: consecutive in the mesh (a hierarchy's leaves depth first,
//! a uniform mesh's rows), in one plane, up to [`RUN`] of them. A run is seen by one ray
//! too: to one of its leaves, `k` with probability `u_k / U` (`u_k` its light unoccluded by
//! all the fields read, `U` the run's), whose light is weighed by `U / u_k`; over the picks
//! the mean is each leaf's light times what its points see, summed over the run, so the
//! estimate stays unbiased. Its noise is the spread of the leaves' visibility and of their
//! light against `u` (`docs/design.md` (5.4a); `docs/accuracy.md`, "Runs of small leaves").

use super::cut::Worth;
use crate::geometry::Patch;
use glam::DVec3;

/// Most leaves of small light seen by one ray together.
pub const RUN: usize = 8;

/// Consecutive leaves `start..end` of the mesh seen by one ray; one leaf, seen as its cut
/// says, when `end = start + 1`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Run {
    pub start: usize,
    pub end: usize,
}

/// The runs of a gather: every leaf that sends light (`worth.lit`) in one of them; a leaf
/// that `alone` names (glossy, or not of small light) in a run of its own.
pub(super) fn runs(patches: &[Patch], worth: &Worth, alone: impl Fn(usize) -> bool) -> Vec<Run> {
    let mut runs: Vec<Run> = Vec::new();
    let mut open: Option<(Run, usize)> = None;
    for j in (0..patches.len()).filter(|&j| worth.lit(j)) {
        if alone(j) {
            runs.extend(open.take().map(|(run, _)| run));
            runs.push(Run { start: j, end: j + 1 });
            continue;
        }
        open = match open {
            Some((run, n)) if n < RUN && patches[run.start].normal == patches[j].normal => {
                Some((Run { end: j + 1, ..run }, n + 1))
            }
            other => {
                runs.extend(other.map(|(run, _)| run));
                Some((Run { start: j, end: j + 1 }, 1))
            }
        };
    }
    runs.extend(open.map(|(run, _)| run));
    runs
}

impl Run {
    /// The leaf the run's ray goes to and the weight of its light: `(k, U / u_k)`, `k`
    /// picked with probability `u_k / U` by the hash `h`; the leaf itself, weighed 1, for a
    /// run of one.
    pub(super) fn pick(&self, worth: &Worth, h: u64) -> (usize, f64) {
        if self.end == self.start + 1 {
            return (self.start, 1.0);
        }
        let lit = || (self.start..self.end).map(|k| (k, worth.light(k))).filter(|&(_, u)| u > 0.0);
        let all: f64 = lit().map(|(_, u)| u).sum();
        let mut left = all * (h as f64 / HASH_RANGE);
        let mut last = None;
        for (k, u) in lit() {
            if left < u {
                return (k, all / u);
            }
            left -= u;
            last = Some((k, all / u));
        }
        last.expect("a run holds a leaf that sends light")
    }
}

/// The hashes of [`pick`] lie in `0..HASH_RANGE`.
const HASH_RANGE: f64 = (1u64 << 35) as f64;

/// A number for the gather at `p` and its leaf (or run) `j`, spread over `0..2³⁵`: which of
/// a leaf's points its one ray goes to, or which leaf of a run, the same for every run.
pub(super) fn pick(p: DVec3, j: usize) -> u64 {
    let mut h = p.to_array().iter().fold(j as u64, |h, x| (h ^ x.to_bits()).wrapping_mul(0x9E37_79B9_7F4A_7C15));
    h ^= h >> 31;
    h.wrapping_mul(0xBF58_476D_1CE4_E5B9) >> 29
}
