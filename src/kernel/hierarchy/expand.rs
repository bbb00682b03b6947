//! The hierarchy's `G` written out on the leaves (`docs/design.md` §3b, "Apply K x" read as a
//! matrix): for the methods and norms that need the explicit product `B·G`. Row `(a, d)` of leaf
//! `a` sums, over each bundle of an ancestor `p` (with `a`'s push share `w`) and each piece
//! `f` of `p`'s links from `q`, `w f` times the pull weight `ω_b` of every leaf `b` under
//! `q` (the product of area shares down the tree, and of shares of the piece's facing value
//! below a cluster): in `b`'s cell `m` when `q` is an element, spread as `μ_m/π` over all
//! `b`'s cells when `q` is a cluster (whose values are cell-weighted means); times `a`'s receiving and `b`'s sending balancing factor
//! (`balance.rs`). Every pair of leaves lies under exactly one link, so the
//! expansion has one entry per visible pair and cell pair, like the uniform kernel.

use super::link::ALL_CELLS;
use super::operator::Operator;

impl Operator {
    /// Calls `f(column, value)` for every entry of row `row = a·K + d` of `G` on the leaves
    /// (a column may come twice when two cell pieces meet; callers sum).
    pub fn for_each_in_row(&self, row: usize, mut f: impl FnMut(usize, f64)) {
        let (k, a, d) = (self.k, row / self.k, row % self.k);
        for &(bundle, w) in &self.push[self.push_row[a]..self.push_row[a + 1]] {
            let (bundle, w) = (bundle as usize, f64::from(w) * self.receive[a]);
            for e in &self.entries[self.row[bundle]..self.row[bundle + 1]] {
                let c = match e.d {
                    ALL_CELLS => w * e.f * self.share[d],
                    cell if cell as usize == d => w * e.f,
                    _ => continue,
                };
                let source = e.source as usize;
                for (b, omega) in self.leaves_under(source, e.m as usize) {
                    let omega = omega * self.send[b];
                    if self.cluster[source] {
                        self.share.iter().enumerate().for_each(|(m, s)| f(b * k + m, c * omega * s));
                    } else {
                        f(b * k + e.m as usize, c * omega);
                    }
                }
            }
        }
    }

    /// Entries of row `row` of the expansion, counted without forming them.
    pub fn row_len(&self, row: usize) -> usize {
        let (k, a, d) = (self.k, row / self.k, row % self.k);
        let mut count = 0;
        for &(bundle, _) in &self.push[self.push_row[a]..self.push_row[a + 1]] {
            let bundle = bundle as usize;
            for e in &self.entries[self.row[bundle]..self.row[bundle + 1]] {
                if e.d == ALL_CELLS || e.d as usize == d {
                    let source = e.source as usize;
                    let leaves = self.leaf_range(source).len();
                    count += if self.cluster[source] { leaves * k } else { leaves };
                }
            }
        }
        count
    }

    /// The leaves (unknown order) under depth-first position `pos`.
    fn leaf_range(&self, pos: usize) -> std::ops::Range<usize> {
        let first = self.leaf_position.partition_point(|&p| (p as usize) < pos);
        let end = self.leaf_position.partition_point(|&p| p < self.subtree_end[pos]);
        first..end
    }

    /// Each leaf under `pos` with its pull weight `ω_b` in `pos`'s value `m`: the product of
    /// the area shares from the leaf up to `pos`, of the shares of facing value `m` from the
    /// way into a cluster on.
    fn leaves_under(&self, pos: usize, m: usize) -> impl Iterator<Item = (usize, f64)> + '_ {
        self.leaf_range(pos).map(move |b| {
            let (mut at, mut omega) = (self.leaf_position[b] as usize, 1.0);
            while at != pos {
                omega *= if self.into_cluster[at] { self.facing_share[at][m] } else { self.weight[at] };
                at = self.parent[at] as usize;
            }
            (b, omega)
        })
    }
}
