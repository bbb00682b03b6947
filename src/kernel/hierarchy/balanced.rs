//! The hierarchy's `G` on its current leaves (`docs/design.md` §3b, "Balance"): the operator
//! of its links, balanced to the leaves' closures unless the options say not.

use super::kernel::Hierarchy;
use super::operator::Operator;

impl Hierarchy {
    /// `G` on the current leaves, balanced to their closures unless `options.balance` is
    /// off (the rays of new leaves' closures count in the work).
    pub fn operator(&mut self) -> Operator {
        let mut operator = Operator::new(&self.tree, &self.links, &self.directions, &mut self.memo.seen);
        if self.options.balance {
            let leaves = operator.leaves().to_vec();
            self.work.rays += self.memo.measure_closure(&self.tree, &self.backs, &self.visibility, &leaves);
            let targets = self.closure_targets(&operator, &leaves);
            let areas: Vec<f64> = leaves.iter().map(|&id| self.tree.node(id).exposed).collect();
            let start = leaves.iter().map(|&id| self.memo.last_factors(&self.tree, id)).unzip();
            operator.balance(&targets, &areas, start);
            self.memo.keep_factors(self.tree.len(), &leaves, &operator.receive, &operator.send);
        }
        operator
    }

    /// Each leaf's row sum to balance to: its links' own (`G·1`, unbalanced) unless its
    /// closure rays tell it apart from the closure (all of them met a front and the row is
    /// not 1, or it lies beyond three standard errors), then the rays' closure.
    fn closure_targets(&self, operator: &Operator, leaves: &[u32]) -> Vec<f64> {
        let k = operator.cells();
        let mut rows = vec![0.0; operator.dim()];
        operator.arriving(&vec![1.0; operator.dim()], &mut rows);
        leaves
            .iter()
            .zip(rows.chunks(k))
            .map(|(&id, row)| {
                let row: f64 = row.iter().sum();
                let rays = self.memo.closure(id);
                if rays.cast == 0 || rays.admits(row) { row } else { rays.share() }
            })
            .collect()
    }
}
