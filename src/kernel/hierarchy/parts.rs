//! The hierarchy's operator as plain arrays (`docs/design.md` §3b, "Apply K x";
//! `docs/kernel-file.md`, "The hierarchical kernel"): what a kernel file stores so that
//! the operator is applied again without its tree's geometry, its rays or its refinement.
//! Every node is indexed by its depth-first position: the pull `R` is `parent` and
//! `weight` (a cluster's value the cell-weighted mean of its children's), the links `Λ`
//! are the gathered pieces by bundle (`row`, `entries`), the push `P` is each leaf's
//! bundles and shares (`push_row`, `push`), and the balancing diagonals are `receive` and
//! `send`: `G = diag(receive) P Λ R diag(send)`. [`Parts::check`] checks every index and
//! value read from a file before the operator is made of them.

use super::link::ALL_CELLS;
use super::node::{FACING, NONE};
use crate::kernel::BalanceReport;

/// One gathered piece: `z[receiver, d] += f · x̄[source, m]` (`d` = [`ALL_CELLS`]: `μ_d/π` each).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Entry {
    /// Depth-first position of the source node.
    pub source: u32,
    /// Receiver cell, or [`ALL_CELLS`].
    pub d: u16,
    /// Source cell; for a cluster source, which of its [`FACING`] values: the mean of its
    /// elements facing `+x, −x, +y, −y, +z` or `−z`.
    pub m: u16,
    /// The factor of the piece.
    pub f: f64,
}

/// The arrays of an [`Operator`](super::Operator).
#[derive(Debug, Clone, PartialEq)]
pub struct Parts {
    /// Tree node id of each leaf, in unknown order.
    pub leaves: Vec<u32>,
    /// Depth-first position of each leaf (ascending).
    pub leaf_position: Vec<u32>,
    /// By depth-first position: the parent's position ([`NONE`] at the top).
    pub parent: Vec<u32>,
    /// By depth-first position: the share of the node's exposed area in its parent's.
    pub weight: Vec<f64>,
    /// By depth-first position: true for a cluster.
    pub cluster: Vec<bool>,
    /// By depth-first position: under a cluster, the node's share of its parent's exposed
    /// area facing each axis direction (`Node::facing`; zeros under an element).
    pub facing_share: Vec<[f64; FACING]>,
    /// The bundles each leaf's ancestors receive with its share of them, CSR by leaf:
    /// `push[push_row[l]..push_row[l + 1]]` holds `(bundle, share)`.
    pub push_row: Vec<usize>,
    /// See `push_row`.
    pub push: Vec<(u32, f32)>,
    /// The gathered pieces of each bundle, CSR: `entries[row[b]..row[b + 1]]`.
    pub row: Vec<usize>,
    /// See `row`.
    pub entries: Vec<Entry>,
    /// Number of links the pieces come from.
    pub links: usize,
    /// Each leaf's receiving balancing factor.
    pub receive: Vec<f64>,
    /// Each leaf's sending balancing factor.
    pub send: Vec<f64>,
    /// How balancing went (`None`: not balanced).
    pub balanced: Option<BalanceReport>,
}

impl Parts {
    /// Checks that the arrays make an operator over `k` cells: lengths, a depth-first
    /// tree, indices in range, finite values.
    pub fn check(&self, k: usize) -> Result<(), String> {
        let (nodes, leaves) = (self.parent.len(), self.leaves.len());
        let bundles = self.row.len().checked_sub(1).ok_or("the gather has no row pointer")?;
        if self.weight.len() != nodes || self.cluster.len() != nodes || self.facing_share.len() != nodes {
            return Err(format!(
                "{nodes} parents, {} weights, {} cluster flags and {} facing shares",
                self.weight.len(),
                self.cluster.len(),
                self.facing_share.len()
            ));
        }
        if self.leaf_position.len() != leaves || self.receive.len() != leaves || self.send.len() != leaves {
            return Err(format!("{leaves} leaves but {} positions or balancing factors", self.leaf_position.len()));
        }
        depth_first(&self.parent)?;
        if self.leaf_position.windows(2).any(|w| w[0] >= w[1])
            || self.leaf_position.iter().any(|&p| p as usize >= nodes)
        {
            return Err("the leaves' positions are not ascending positions of the tree".into());
        }
        pointers(&self.push_row, leaves, self.push.len(), "push")?;
        pointers(&self.row, bundles, self.entries.len(), "gather")?;
        if self.push.iter().any(|&(b, w)| b as usize >= bundles || !w.is_finite()) {
            return Err(format!("a push share names a bundle beyond {bundles} or is not finite"));
        }
        let cell = |c: u16| (c as usize) < k;
        let value = |e: &Entry| (e.m as usize) < if self.cluster[e.source as usize] { FACING } else { k };
        if self.entries.iter().any(|e| e.source as usize >= nodes || !(cell(e.d) || e.d == ALL_CELLS) || !value(e)) {
            return Err(format!(
                "a gathered piece names a node beyond {nodes}, a cell beyond {k} or a cluster's facing beyond {FACING}"
            ));
        }
        let finite = |v: &[f64]| v.iter().all(|x| x.is_finite());
        let factors = self.entries.iter().all(|e| e.f.is_finite());
        let shares = finite(self.facing_share.as_flattened());
        if !(finite(&self.weight) && finite(&self.receive) && finite(&self.send) && factors && shares) {
            return Err("a weight, factor or balancing factor is not finite".into());
        }
        Ok(())
    }
}

/// Checks that `parent` lists a tree in depth-first order: the top first, and every other
/// node's parent the node before it or one of that node's ancestors.
fn depth_first(parent: &[u32]) -> Result<(), String> {
    let mut path: Vec<u32> = Vec::new();
    for (pos, &p) in parent.iter().enumerate() {
        while path.last().is_some_and(|&top| top != p) {
            path.pop();
        }
        if (p == NONE) != (pos == 0) || (pos > 0 && path.is_empty()) {
            return Err(format!("node {pos} of the depth-first order has parent {p}"));
        }
        path.push(pos as u32);
    }
    Ok(())
}

/// Checks a CSR row pointer of `rows` rows over `len` entries.
fn pointers(row: &[usize], rows: usize, len: usize, what: &str) -> Result<(), String> {
    if row.len() != rows + 1
        || row.first() != Some(&0)
        || row.last() != Some(&len)
        || row.windows(2).any(|w| w[0] > w[1])
    {
        return Err(format!("the {what} pointers do not delimit {len} entries in {rows} rows"));
    }
    Ok(())
}
