//! `G x` on the leaf unknowns (`docs/design.md` §3b, "Apply K x"): pull (leaf values up the trees
//! as area averages; into a cluster as the cell-weighted mean `Σ_m (μ_m/π) x_m`, which means
//! the same in every frame, averaged six times, over the exposed area facing each axis
//! direction: a cluster's light towards a receiver is its elements' that face it), gather
//! over the links at every level (`z_p += F_pq x̄_q`, by cells), push (each node's gathered
//! light to all its leaves, each leaf with its own share, `push.rs`). The material blocks
//! are the kernel's (`crate::kernel::Kernel`), as for the uniform kernel's `G`. Nodes are
//! stored in depth-first order, so pull is one backward sweep; gather (over receivers) and
//! push (over leaves) run in parallel. Nothing is allocated per application.

use super::bundle::Bundles;
use super::link::{ALL_CELLS, Link, axis};
use super::node::{FACING, NONE};
use super::parts::{Entry, Parts};
use super::push::{SeenCache, gathered, push_rows};
use super::tree::Tree;
use crate::directions::DirectionSet;
use crate::kernel::BalanceReport;
use crate::progress::Progress;
use crate::visibility::Visibility;
use rayon::prelude::*;
use std::f64::consts::PI;
use std::sync::Mutex;

/// Most partial sums a scatter of `Gᵀ y` keeps side by side, one per task (`transpose.rs`):
/// each beyond the first costs the larger of `bundles × K` and `nodes × K` values.
pub(super) const MOST_LANES: usize = 4;

/// Work arrays: `nodes × max(K, 6)` (means: an element's `K` cells, a cluster's six facing
/// values), `bundles × K` (gathered light) and `leaves × K` (sent light), shared
/// by `G x` and `Gᵀ y` (`transpose.rs`); and the partial sums of `Gᵀ y`'s scatters beside
/// the first (one fewer than the threads, at most [`MOST_LANES`], of the larger of
/// `nodes × K` and `bundles × K`).
pub(super) struct Scratch {
    sent: Vec<f64>,
    pub(super) mean: Vec<f64>,
    pub(super) gathered: Vec<f64>,
    pub(super) spare: Vec<f64>,
}

/// The hierarchical transport `G` as an operator on `x[leaf·K + k]`.
pub struct Operator {
    pub(super) k: usize,
    /// Tree node of each leaf, in unknown order.
    leaves: Vec<u32>,
    /// Depth-first position of each leaf (ascending).
    pub(super) leaf_position: Vec<u32>,
    /// The bundles each leaf's ancestors receive and its share of their light (CSR, `push.rs`).
    pub(super) push_row: Vec<usize>,
    pub(super) push: Vec<(u32, f32)>,
    /// By depth-first position: parent position ([`NONE`] at the top), area share in the
    /// parent, and whether the parent is a cluster.
    pub(super) parent: Vec<u32>,
    pub(super) weight: Vec<f64>,
    pub(super) into_cluster: Vec<bool>,
    /// By depth-first position: under a cluster, the node's share of each of its parent's
    /// six facing values (`Parts::facing_share`).
    pub(super) facing_share: Vec<[f64; FACING]>,
    /// Values per node in the means: `max(K, 6)`.
    pub(super) stride: usize,
    /// By depth-first position: one past the last position of its subtree, and whether it is
    /// a cluster (for the expansion, `expand.rs`).
    pub(super) subtree_end: Vec<u32>,
    pub(super) cluster: Vec<bool>,
    /// Gathered pieces by bundle (CSR, `bundle.rs`).
    pub(super) row: Vec<usize>,
    pub(super) entries: Vec<Entry>,
    links: usize,
    /// `μ_d/π` of each cell.
    pub(super) share: Vec<f64>,
    /// Each leaf's balancing factors (`balance.rs`): what it receives and what it sends
    /// are scaled by them; 1 until balanced.
    pub(super) receive: Vec<f64>,
    pub(super) send: Vec<f64>,
    /// How balancing these factors went (`None`: not balanced).
    pub(super) balanced: Option<BalanceReport>,
    pub(super) scratch: Mutex<Scratch>,
}

impl Operator {
    /// The operator of `links` over the leaves of `tree` (whose faces `visibility` holds);
    /// the leaves' views of their sources are kept in `seen` from one build to the next
    /// (`push.rs`); `progress` hears of the leaves whose push rows are done.
    pub fn new(
        tree: &Tree,
        (visibility, links): (&Visibility, &[Link]),
        directions: &DirectionSet,
        seen: &mut SeenCache,
        progress: &dyn Progress,
    ) -> Operator {
        let order = tree.preorder();
        let mut position = vec![NONE; tree.len()];
        for (pos, &id) in order.iter().enumerate() {
            position[id as usize] = pos as u32;
        }
        let (parent, weight) = parents(tree, &order, &position);
        let cluster = order.iter().map(|&id| tree.node(id).patch().is_none()).collect();
        let facing_share = facing_shares(tree, &order);
        let leaves: Vec<u32> = order.iter().copied().filter(|&id| tree.node(id).is_leaf()).collect();
        let leaf_position = leaves.iter().map(|&id| position[id as usize]).collect();
        let bundles = Bundles::new(tree, links, &position);
        let (push_row, push) = push_rows(tree, visibility, (links, &bundles), &leaves, seen, progress);
        let (row, entries) = gather_rows(tree, links, &bundles, &position);
        let n = leaves.len();
        let parts = Parts {
            leaves,
            leaf_position,
            parent,
            weight,
            cluster,
            facing_share,
            push_row,
            push,
            row,
            entries,
            links: links.len(),
            receive: vec![1.0; n],
            send: vec![1.0; n],
            balanced: None,
        };
        Operator::of(parts, directions)
    }

    /// The operator of `parts` with the cells of `directions` (checked by the caller,
    /// `Parts::check`).
    pub(super) fn of(parts: Parts, directions: &DirectionSet) -> Operator {
        let k = directions.len();
        let Parts {
            leaves,
            leaf_position,
            parent,
            weight,
            cluster,
            facing_share,
            push_row,
            push,
            row,
            entries,
            links,
            ..
        } = parts;
        let into_cluster = parent.iter().map(|&p| p != NONE && cluster[p as usize]).collect();
        let subtree_end = subtree_ends(&parent);
        let (nodes, dim, bundles, stride) = (parent.len(), leaves.len() * k, row.len() - 1, k.max(FACING));
        Operator {
            k,
            leaves,
            leaf_position,
            push_row,
            push,
            parent,
            weight,
            into_cluster,
            facing_share,
            stride,
            subtree_end,
            cluster,
            row,
            entries,
            links,
            share: directions.cells().iter().map(|c| c.projected / PI).collect(),
            receive: parts.receive,
            send: parts.send,
            balanced: parts.balanced,
            scratch: Mutex::new(Scratch {
                sent: vec![0.0; dim],
                mean: vec![0.0; nodes * stride],
                gathered: vec![0.0; bundles * k],
                spare: vec![
                    0.0;
                    (rayon::current_num_threads().clamp(1, MOST_LANES) - 1) * (nodes * stride).max(bundles * k)
                ],
            }),
        }
    }

    /// Number of unknowns, leaves × K.
    pub fn dim(&self) -> usize {
        self.leaves.len() * self.k
    }

    /// Tree node of each leaf, in unknown order.
    pub fn leaves(&self) -> &[u32] {
        &self.leaves
    }

    /// Number of links gathered.
    pub fn links(&self) -> usize {
        self.links
    }

    /// Direction cells per leaf, `K`.
    pub fn cells(&self) -> usize {
        self.k
    }

    /// How balancing went (`None`: not balanced).
    pub fn balanced(&self) -> Option<BalanceReport> {
        self.balanced
    }

    /// Gathered pieces of all links (one per link for `K = 1`, one per cell pair otherwise).
    pub fn pieces(&self) -> usize {
        self.entries.len()
    }

    /// Bytes held: the pieces, the push weights, the per-node arrays and the work arrays.
    pub fn bytes(&self) -> f64 {
        let nodes = self.parent.len() as f64;
        let per_node = 4.0 + 8.0 + 1.0 + 8.0 + 8.0 * FACING as f64 + 8.0 * (self.k + self.stride) as f64;
        let per_leaf = 4.0 * 2.0 + 3.0 * 8.0 + 8.0 * self.k as f64;
        (self.entries.len() * std::mem::size_of::<Entry>() + self.push.len() * std::mem::size_of::<(u32, f32)>()) as f64
            + nodes * per_node
            + self.leaves.len() as f64 * per_leaf
    }

    /// `z = G x`: the light arriving at every leaf and cell (as `Kernel::apply_transport`;
    /// illuminance `E = π Σ_d z_d`, lx).
    pub fn arriving(&self, x: &[f64], z: &mut [f64]) {
        let mut s = self.scratch.lock().unwrap_or_else(|e| e.into_inner());
        let Scratch { sent, mean, gathered, .. } = &mut *s;
        self.transport(x, sent, mean, gathered, z);
    }

    /// Pull, gather, push, each leaf's light scaled by its sending and receiving factors:
    /// `arriving` holds every leaf's arriving light afterwards.
    fn transport(&self, x: &[f64], sent: &mut [f64], mean: &mut [f64], gathered: &mut [f64], arriving: &mut [f64]) {
        let k = self.k;
        sent.par_chunks_mut(k).zip(x.par_chunks(k)).zip(&self.send).for_each(|((out, x), s)| {
            out.iter_mut().zip(x).for_each(|(o, x)| *o = s * x);
        });
        self.pull(sent, mean);
        self.gather(mean, gathered);
        self.push(gathered, arriving);
    }

    /// Area averages of the leaf values at every node; a cluster's six, each over its
    /// elements' exposed area facing one axis direction.
    fn pull(&self, x: &[f64], mean: &mut [f64]) {
        let (k, stride) = (self.k, self.stride);
        mean.fill(0.0);
        for (l, &pos) in self.leaf_position.iter().enumerate() {
            mean[pos as usize * stride..][..k].copy_from_slice(&x[l * k..(l + 1) * k]);
        }
        for pos in (1..self.parent.len()).rev() {
            let (up, down) = mean.split_at_mut(pos * stride);
            let parent = &mut up[self.parent[pos] as usize * stride..][..stride];
            let child = &down[..stride];
            if !self.into_cluster[pos] {
                let w = self.weight[pos];
                parent[..k].iter_mut().zip(&child[..k]).for_each(|(p, c)| *p += w * c);
                continue;
            }
            let shares = self.facing_share[pos].iter().zip(parent.iter_mut());
            match self.cluster[pos] {
                true => shares.zip(child).for_each(|((s, p), c)| *p += s * c),
                false => {
                    let m: f64 = child[..k].iter().zip(&self.share).map(|(v, s)| v * s).sum();
                    shares.for_each(|(s, p)| *p += s * m);
                }
            }
        }
    }

    /// `z_b = Σ_q F_pq x̄_q` over every bundle's links, in parallel over bundles.
    fn gather(&self, mean: &[f64], gathered: &mut [f64]) {
        let (k, stride) = (self.k, self.stride);
        gathered.par_chunks_mut(k).enumerate().for_each(|(b, z)| {
            z.fill(0.0);
            for e in &self.entries[self.row[b]..self.row[b + 1]] {
                let v = e.f * mean[e.source as usize * stride + e.m as usize];
                if e.d == ALL_CELLS {
                    z.iter_mut().zip(&self.share).for_each(|(z, s)| *z += v * s);
                } else {
                    z[e.d as usize] += v;
                }
            }
        });
    }

    /// Every leaf's share of the light its ancestors' bundles gathered (times its receiving
    /// factor), in parallel over leaves.
    fn push(&self, gathered: &[f64], arriving: &mut [f64]) {
        let k = self.k;
        arriving.par_chunks_mut(k).enumerate().for_each(|(l, z)| {
            z.fill(0.0);
            for &(b, w) in &self.push[self.push_row[l]..self.push_row[l + 1]] {
                let g = &gathered[b as usize * k..(b as usize + 1) * k];
                let w = f64::from(w) * self.receive[l];
                z.iter_mut().zip(g).for_each(|(z, g)| *z += w * g);
            }
        });
    }
}

impl Operator {
    /// A copy of the operator's arrays.
    pub fn parts(&self) -> Parts {
        Parts {
            leaves: self.leaves().to_vec(),
            leaf_position: self.leaf_position.clone(),
            parent: self.parent.clone(),
            weight: self.weight.clone(),
            cluster: self.cluster.clone(),
            facing_share: self.facing_share.clone(),
            push_row: self.push_row.clone(),
            push: self.push.clone(),
            row: self.row.clone(),
            entries: self.entries.clone(),
            links: self.links(),
            receive: self.receive.clone(),
            send: self.send.clone(),
            balanced: self.balanced,
        }
    }

    /// The operator of `parts` over the cells of `directions`, or what is wrong with them.
    pub fn from_parts(parts: Parts, directions: &DirectionSet) -> Result<Operator, String> {
        parts.check(directions.len())?;
        Ok(Operator::of(parts, directions))
    }
}

/// Parent position and area share in the parent of every depth-first position.
pub(super) fn parents(tree: &Tree, order: &[u32], position: &[u32]) -> (Vec<u32>, Vec<f64>) {
    let mut parent = vec![NONE; order.len()];
    let mut weight = vec![0.0; order.len()];
    for (pos, &id) in order.iter().enumerate() {
        let children = tree.children(id);
        let total: f64 = children.iter().map(|&c| tree.node(c).exposed).sum();
        for &c in children {
            let cp = position[c as usize] as usize;
            parent[cp] = pos as u32;
            weight[cp] = if total > 0.0 { tree.node(c).exposed / total } else { 0.0 };
        }
    }
    (parent, weight)
}

/// By depth-first position (`order`): under a cluster, the node's share of each of its
/// parent's facing areas (`Node::facing`; 0 where the parent faces none that way).
pub(super) fn facing_shares(tree: &Tree, order: &[u32]) -> Vec<[f64; FACING]> {
    order
        .iter()
        .map(|&id| {
            let node = tree.node(id);
            match node.parent {
                NONE => [0.0; FACING],
                up if tree.node(up).patch().is_some() => [0.0; FACING],
                up => {
                    let (whole, open) = (tree.node(up).facing, tree.open(id));
                    std::array::from_fn(|c| if whole[c] > 0.0 { node.facing[c] * open[c] / whole[c] } else { 0.0 })
                }
            }
        })
        .collect()
}

/// One past the last depth-first position of every position's subtree.
fn subtree_ends(parent: &[u32]) -> Vec<u32> {
    let mut end: Vec<u32> = (1..=parent.len() as u32).collect();
    for pos in (0..parent.len()).rev().filter(|&pos| parent[pos] != NONE) {
        let up = parent[pos] as usize;
        end[up] = end[up].max(end[pos]);
    }
    end
}

/// The links' pieces as CSR rows by bundle, each link's factor without its visible fraction
/// (`push.rs`: each leaf's own rays see the rest); a cluster source's pieces split between
/// its facing values towards the receiver (`Node::facing_weights`).
pub(super) fn gather_rows(
    tree: &Tree,
    links: &[Link],
    bundles: &Bundles,
    position: &[u32],
) -> (Vec<usize>, Vec<Entry>) {
    let mut row = Vec::with_capacity(bundles.len() + 1);
    row.push(0);
    let mut entries = Vec::with_capacity(bundles.links.len());
    for b in 0..bundles.len() {
        for &l in bundles.links_of(b) {
            pieces_of(tree, &links[l as usize], position, &mut entries);
        }
        row.push(entries.len());
    }
    (row, entries)
}

/// The gathered pieces of `link` added to `entries`.
fn pieces_of(tree: &Tree, link: &Link, position: &[u32], entries: &mut Vec<Entry>) {
    let source = position[link.source as usize];
    let f = gathered(tree, link);
    let open = if link.factor > 0.0 { f / link.factor } else { 1.0 };
    let scaled = link.pieces.iter().map(|&(d, m, f)| (d, m, f * open));
    let pieces = scaled.chain(link.pieces.is_empty().then_some((0, 0, f)));
    let (q, p) = (tree.node(link.source), tree.node(link.receiver));
    if q.patch().is_some() {
        entries.extend(pieces.map(|(d, m, f)| Entry { source, d, m, f }));
        return;
    }
    let towards = q.facing_weights(-axis(p, q).0);
    for (d, _, f) in pieces {
        let by_facing = towards.iter().enumerate().filter(|(_, w)| **w > 0.0);
        entries.extend(by_facing.map(|(m, w)| Entry { source, d, m: m as u16, f: f * w }));
    }
}
