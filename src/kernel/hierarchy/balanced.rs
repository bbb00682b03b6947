//! The hierarchy's `G` on its current leaves (`docs/design.md` §3b, "Balance"): the operator
//! of its links, balanced to the leaves' closures unless the options say not.

use super::kernel::Hierarchy;
use super::operator::Operator;
use crate::progress::Progress;

/// How far a leaf's sending factor may move from 1, in link tolerances: a link is kept while
/// its error is below the tolerance times the scene's mean reflected luminance, so a column
/// off by more than a few tolerances is the spread of closure its ancestors' links carry as
/// their mean, not their error (`balance.rs`). At 3 the integrating sphere's factors (within
/// 2.3 %) stay free; the open box's (5th–95th percentile 0.86–1.11) are held.
pub(super) const SENDING: f64 = 3.0;

impl Hierarchy {
    /// `G` on the current leaves, balanced to their closures unless `options.balance` is
    /// off (the rays of new leaves' closures count in the work); `progress` hears of the
    /// leaves whose push rows are done.
    pub fn operator(&mut self, progress: &dyn Progress) -> Operator {
        let start = std::time::Instant::now();
        let parts = (&self.visibility, &self.links[..]);
        let mut operator = Operator::new(&self.tree, parts, &self.directions, &mut self.memo.seen, progress);
        if self.options.balance {
            let leaves = operator.leaves().to_vec();
            self.work.rays += self.memo.measure_closure(&self.tree, &self.backs, &self.visibility, &leaves);
            let areas: Vec<f64> = leaves.iter().map(|&id| self.tree.node(id).exposed).collect();
            let targets = self.closure_targets(&operator, &leaves, &areas);
            let start = leaves.iter().map(|&id| self.memo.last_factors(&self.tree, id)).unzip();
            operator.balance(&targets, &areas, start, SENDING * self.options.tolerance);
            self.memo.keep_factors(self.tree.len(), &leaves, &operator.receive, &operator.send);
        }
        self.work.operator_seconds += start.elapsed().as_secs_f64();
        operator
    }

    /// Refinement is over: frees what only a later pass's operator would reuse (the push's
    /// leaves' views, `push.rs`); a later operator finds them again.
    pub fn refined(&mut self) {
        self.memo.seen.forget();
    }

    /// Each leaf's row sum to balance to. An emitting leaf's own estimate is its column,
    /// what the others receive from it per unit of its area (`Σ_i A_i G_ij / A_j`): its
    /// links as a source are refined against its brightness, while as a receiver a dark
    /// emitter's are never refined. Another leaf's is its row (`G·1`). Either stands unless
    /// its closure rays tell it apart from the closure (all of them met a front and it is
    /// not 1, or it lies beyond three standard errors); then the rays' closure does.
    fn closure_targets(&self, operator: &Operator, leaves: &[u32], areas: &[f64]) -> Vec<f64> {
        let k = operator.cells();
        let mut rows = vec![0.0; operator.dim()];
        operator.arriving(&vec![1.0; operator.dim()], &mut rows);
        // columns only where some leaf emits: `leaving` is one serial scatter over the links
        let emits = |id: u32| self.tree.node(id).emission > 0.0;
        let mut columns = vec![0.0; operator.dim()];
        if leaves.iter().any(|&id| emits(id)) {
            let weights: Vec<f64> = areas.iter().flat_map(|&a| std::iter::repeat_n(a, k)).collect();
            operator.leaving(&weights, &mut columns);
        }
        leaves
            .iter()
            .enumerate()
            .map(|(l, &id)| {
                let own = match emits(id) && areas[l] > 0.0 {
                    true => columns[l * k..(l + 1) * k].iter().sum::<f64>() / areas[l],
                    false => rows[l * k..(l + 1) * k].iter().sum(),
                };
                let rays = self.memo.closure(id);
                if rays.cast == 0 || rays.admits(own) { own } else { rays.share() }
            })
            .collect()
    }
}
