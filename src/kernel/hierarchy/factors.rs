//! The hierarchy's `G` as a product of sparse matrices (`docs/design.md` §3b, "Apply K x";
//! issue 36; `docs/kernel-file.md`, "Exporting the hierarchy"): with every tree node as an
//! unknown, `G = diag(r) · P · Λ · R · diag(s)` on the leaves, where `R` pulls (node ←
//! area-weighted mean of its leaves), `Λ` gathers (bundle ← node, the links' pieces), `P`
//! pushes (leaf ← its ancestors' bundles, by its share) and `r`, `s` are the receiving and
//! sending balancing factors, each repeated over the `K` cells of a leaf. Rows and columns
//! are `(index · K + cell)` for leaves and bundles, `(position · S + value)` for nodes,
//! `S = max(K, 6)`: an element's `K` cells, a cluster's six facing values (each the
//! cell-weighted mean of its elements facing one axis direction, `operator.rs`). Built from
//! the operator's own arrays, so the product equals `Operator::arriving` to rounding.

use super::link::ALL_CELLS;
use super::node::{FACING, NONE};
use super::operator::Operator;
use sprs::{CsMat, TriMat};

/// The factors of `G = diag(receive) · P · Λ · R · diag(send)`.
pub struct Factors {
    /// Push, `(leaves·K) × (bundles·K)`.
    pub push: CsMat<f64>,
    /// Links, `(bundles·K) × (nodes·S)`.
    pub links: CsMat<f64>,
    /// Pull, `(nodes·S) × (leaves·K)`.
    pub pull: CsMat<f64>,
    /// The receiving balancing factor of every unknown, `leaves·K`.
    pub receive: Vec<f64>,
    /// The sending balancing factor of every unknown, `leaves·K`.
    pub send: Vec<f64>,
}

impl Operator {
    /// The operator as its factors.
    pub fn factors(&self) -> Factors {
        let k = self.k;
        let repeat = |v: &[f64]| v.iter().flat_map(|&f| std::iter::repeat_n(f, k)).collect();
        Factors {
            push: self.push_matrix(),
            links: self.links_matrix(),
            pull: self.pull_matrix(),
            receive: repeat(&self.receive),
            send: repeat(&self.send),
        }
    }

    fn push_matrix(&self) -> CsMat<f64> {
        let (k, leaves, bundles) = (self.k, self.leaf_position.len(), self.row.len() - 1);
        let mut tri = TriMat::with_capacity((leaves * k, bundles * k), self.push.len() * k);
        for l in 0..leaves {
            for &(b, w) in &self.push[self.push_row[l]..self.push_row[l + 1]] {
                (0..k).for_each(|d| tri.add_triplet(l * k + d, b as usize * k + d, f64::from(w)));
            }
        }
        tri.to_csr()
    }

    fn links_matrix(&self) -> CsMat<f64> {
        let (k, bundles, nodes) = (self.k, self.row.len() - 1, self.parent.len());
        let mut tri = TriMat::with_capacity((bundles * k, nodes * self.stride), self.entries.len());
        for b in 0..bundles {
            for e in &self.entries[self.row[b]..self.row[b + 1]] {
                let column = e.source as usize * self.stride + e.m as usize;
                match e.d {
                    ALL_CELLS => {
                        self.share.iter().enumerate().for_each(|(d, s)| tri.add_triplet(b * k + d, column, e.f * s))
                    }
                    d => tri.add_triplet(b * k + d as usize, column, e.f),
                }
            }
        }
        tri.to_csr()
    }

    /// Each leaf's weight in every ancestor (itself with 1): the product of the area shares
    /// on the way up, times `μ_m/π` once the way enters a cluster, and from there on each
    /// facing value's product of facing shares.
    fn pull_matrix(&self) -> CsMat<f64> {
        let (k, stride, leaves, nodes) = (self.k, self.stride, self.leaf_position.len(), self.parent.len());
        let mut tri = TriMat::new((nodes * stride, leaves * k));
        for (l, &pos) in self.leaf_position.iter().enumerate() {
            let (mut at, mut omega, mut facing): (usize, f64, Option<[f64; FACING]>) = (pos as usize, 1.0, None);
            loop {
                match facing {
                    Some(by) => self.share.iter().enumerate().for_each(|(m, s)| {
                        by.iter().enumerate().for_each(|(c, w)| tri.add_triplet(at * stride + c, l * k + m, w * s))
                    }),
                    None => (0..k).for_each(|m| tri.add_triplet(at * stride + m, l * k + m, omega)),
                }
                if self.parent[at] == NONE {
                    break;
                }
                facing = match (facing, self.into_cluster[at]) {
                    (Some(by), _) => Some(std::array::from_fn(|c| by[c] * self.facing_share[at][c])),
                    (None, true) => Some(self.facing_share[at].map(|w| omega * w)),
                    (None, false) => {
                        omega *= self.weight[at];
                        None
                    }
                };
                at = self.parent[at] as usize;
            }
        }
        tri.to_csr()
    }
}
