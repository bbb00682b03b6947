//! Closure balancing of the hierarchy's `G` (`docs/design.md` §3b, "Balance"): `G' = R G S`
//! with one receiving factor `r_i` and one sending factor `s_i` per leaf, such that every
//! leaf's row carries its closure `t_i` (`Σ_{j,m,d} G'[(i,d),(j,m)] = t_i`: the white
//! furnace holds on every leaf) and every leaf's light lands on the scene's exposed
//! areas in the same share (`Σ_i A_i Σ_{d,m} G'[(i,d),(j,m)] = A_j t_j`: energy is
//! conserved) as far as its links can carry it. The exact kernel has both properties
//! (reciprocity makes the columns the rows); the hierarchy's links lose them where a few
//! rays between stand-ins decide a whole cluster pair's visibility, or a link is dropped as
//! occluded while part of it is seen. A leaf's column is not its own, though: its light
//! leaves through its ancestors' links as their mean, so its column also differs from its
//! closure by the spread of closure among those ancestors' leaves, which a factor on the
//! leaf cannot mend; scaling it moves light among the sources of every row. So a sending
//! factor stays within `1 ± c` (the caller's `c`, a few link tolerances: what the links'
//! own errors can explain); free, it read the hard probes of umbrae, contacts and dim
//! corners 3–8 % bright (`docs/hierarchy.md`, "Sending factors held to the links' error").
//! The uniform kernel is balanced the same way (`kernel/uniform/balance.rs`, symmetrically:
//! its exchange areas are reciprocal, and its columns are its own). Sinkhorn–Knopp by
//! alternating row and column sweeps (Sinkhorn & Knopp 1967), each one application of `G`
//! and one of `Gᵀ`.

use super::operator::Operator;
use crate::kernel::BalanceReport;

/// Change of the factors at which balancing stops.
const BALANCED: f64 = 1e-6;
/// Row mismatch (once the columns are balanced) at which balancing stops: a tenth of
/// the white furnace's 1e-3, far below what a leaf's closure rays resolve. The lecture
/// hall's rows reach it in 36 sweeps and creep from 5.9e-5 to 4.9e-5 over the next 60.
const ROWS_BALANCED: f64 = 1e-4;
/// Row mismatch below which balancing also stops once a sweep improves it by less than
/// [`STALLED`]: the white furnace's bound. Where rows and columns cannot both be met (the
/// office's rows creep from 6.8e-4 to 5.8e-4 over sweeps 71–100), further sweeps buy
/// nothing that a reading shows.
const FURNACE: f64 = 1e-3;
/// Relative improvement of the row mismatch per sweep under which balancing has stalled.
const STALLED: f64 = 1e-2;
/// Sweeps before balancing gives up (it reports the mismatch it reached).
const MAX_SWEEPS: usize = 100;
/// Largest factor by which a leaf's received light may be scaled either way.
const MOST: f64 = 4.0;

/// The rules of the sweeps by name, for a program that balances the operator from a
/// part's rows (`rows.rs`, `tools/petsc/from_parts.py`).
pub const RULES: [(&str, f64); 6] = [
    ("balanced", BALANCED),
    ("rows_balanced", ROWS_BALANCED),
    ("furnace", FURNACE),
    ("stalled", STALLED),
    ("max_sweeps", MAX_SWEEPS as f64),
    ("most", MOST),
];

impl Operator {
    /// Balances the operator to the leaves' closures `targets` (in leaf order) with their
    /// exposed areas `areas`, m². A leaf with no target, no exposed area, or no light
    /// arriving or leaving keeps its factors at 1; no receiving factor goes beyond [`MOST`]
    /// either way (a leaf whose links carry less than a quarter of its closure stays short,
    /// and the report's residual says by how much), no sending factor beyond `1 + sending`
    /// either way. Sweeps stop when no factor changes by
    /// [`BALANCED`] any more, or once the columns are balanced and the rows of the leaves
    /// within those limits match their targets within [`ROWS_BALANCED`], or within
    /// [`FURNACE`] with a sweep that bettered them by less than [`STALLED`]. The sweeps start
    /// from the factors `start` (receiving, sending; in leaf order): all 1 for a new
    /// operator, else each leaf's (or its nearest ancestor's) in the last operator.
    pub fn balance(
        &mut self,
        targets: &[f64],
        areas: &[f64],
        start: (Vec<f64>, Vec<f64>),
        sending: f64,
    ) -> BalanceReport {
        let (n, k) = (self.leaves().len(), self.cells());
        self.receive = vec![1.0; n];
        self.send = vec![1.0; n];
        let (mut receive, mut send) = start;
        assert!(receive.len() == n && send.len() == n, "one starting factor per leaf");
        let (mut x, mut z) = (vec![0.0; n * k], vec![0.0; n * k]);
        let free = |l: usize| targets[l] > 0.0 && areas[l] > 0.0;
        let mut report = BalanceReport::default();
        let mut last = f64::INFINITY;
        // A signal ends the sweeps (`crate::interrupt`: the caller checks).
        for sweep in (1..=MAX_SWEEPS).take_while(|_| !crate::interrupt::asked()) {
            x.chunks_mut(k).zip(&send).for_each(|(x, s)| x.fill(*s));
            self.arriving(&x, &mut z);
            let rows = sums(&z, k, |_| 1.0);
            let mismatch = row_mismatch(&receive, &rows, targets, &free);
            let stalled = mismatch < FURNACE && mismatch > (1.0 - STALLED) * last;
            if sweep > 1 && (mismatch < ROWS_BALANCED || stalled) {
                break;
            }
            last = mismatch;
            let mut change = rescale(&mut receive, &rows, targets, &free, MOST);
            x.chunks_mut(k).enumerate().for_each(|(l, x)| x.fill(areas[l] * receive[l]));
            self.leaving(&x, &mut z);
            let columns = sums(&z, k, |l| 1.0 / areas[l]);
            change = change.max(rescale(&mut send, &columns, targets, &free, 1.0 + sending));
            report.iterations = sweep;
            if change < BALANCED {
                break;
            }
        }
        // what is left: each row's mismatch once the columns are balanced
        x.chunks_mut(k).zip(&send).for_each(|(x, s)| x.fill(*s));
        self.arriving(&x, &mut z);
        let rows = sums(&z, k, |_| 1.0);
        report.residual = row_mismatch(&receive, &rows, targets, &free);
        report.max_correction = receive.iter().chain(&send).map(|f| (f - 1.0).abs()).fold(0.0, f64::max);
        self.receive = receive;
        self.send = send;
        self.balanced = Some(report);
        report
    }
}

/// The largest `|r_i · row_i / t_i − 1|` over the free leaves whose receiving factors are
/// within [`MOST`] (`rows` with the current sending factors, which their own limit keeps
/// well inside it).
fn row_mismatch(receive: &[f64], rows: &[f64], targets: &[f64], free: &impl Fn(usize) -> bool) -> f64 {
    let within = |f: f64| f > 1.0 / MOST && f < MOST;
    (0..rows.len())
        .filter(|&l| free(l) && within(receive[l]))
        .map(|l| (receive[l] * rows[l] / targets[l] - 1.0).abs())
        .fold(0.0, f64::max)
}

/// Each leaf's sum over its cells of `z`, times `scale(leaf)`.
fn sums(z: &[f64], k: usize, scale: impl Fn(usize) -> f64) -> Vec<f64> {
    z.chunks(k).enumerate().map(|(l, z)| z.iter().sum::<f64>() * scale(l)).collect()
}

/// Sets each free leaf's factor to `target / sum`, at most `most` times or `1/most` of 1;
/// returns the largest relative change.
fn rescale(factors: &mut [f64], sums: &[f64], targets: &[f64], free: &impl Fn(usize) -> bool, most: f64) -> f64 {
    let mut change: f64 = 0.0;
    for (l, f) in factors.iter_mut().enumerate().filter(|(l, _)| free(*l) && sums[*l] > 0.0) {
        let next = (targets[l] / sums[l]).clamp(1.0 / most, most);
        change = change.max((next / *f - 1.0).abs());
        *f = next;
    }
    change
}
