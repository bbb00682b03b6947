//! `Gᵀ y` on the leaf unknowns: the hierarchy's transport (`operator.rs`, `docs/design.md` §3b
//! "Apply K x") run backwards, balancing factors included (`balance.rs`: `(R G S)ᵀ =
//! S Gᵀ R`). Push becomes a sum over each leaf's ancestors, gather a
//! scatter over the links from receiver to source, pull a sweep down the trees (into a
//! cluster: each of its six facing values times the child's share of it, and into an
//! element's cells by their `μ_m/π`). Its uses: the
//! light each leaf sends to the whole scene, `Σ_i A_i G_ij` (the columns that energy
//! conservation constrains), and `‖K‖₁` without the expansion. The two scatters run on up
//! to four tasks, each into partial sums of its own, added after (`docs/performance.md`,
//! "Balancing on both cores").

use super::link::ALL_CELLS;
use super::operator::{MOST_LANES, Operator, Scratch};
use rayon::prelude::*;
use std::ops::Range;

impl Operator {
    /// `x = Gᵀ y` (both `leaves × K`): the push's and the gathers' scatters split between
    /// up to [`MOST_LANES`] tasks, each into its own partial sums, then added. Nothing is
    /// allocated: it works in the operator's own arrays.
    pub fn leaving(&self, y: &[f64], x: &mut [f64]) {
        let k = self.k;
        let mut scratch = self.scratch.lock().unwrap_or_else(|e| e.into_inner());
        let Scratch { gathered, mean, spare, .. } = &mut *scratch;
        let lanes = 1 + spare.len() / gathered.len().max(mean.len()).max(1);
        // the leaves' light back into the bundles their shares came from
        scattered(gathered, spare, &balanced_cuts(&self.push_row, lanes)[..=lanes], |leaves, g| {
            for l in leaves {
                let z = &y[l * k..(l + 1) * k];
                for &(b, w) in &self.push[self.push_row[l]..self.push_row[l + 1]] {
                    let w = f64::from(w) * self.receive[l];
                    g[b as usize * k..][..k].iter_mut().zip(z).for_each(|(g, z)| *g += w * z);
                }
            }
        });
        // each bundle's light back to its sources
        let gathered = &*gathered;
        scattered(mean, spare, &balanced_cuts(&self.row, lanes)[..=lanes], |bundles, mean| {
            for b in bundles {
                let z = &gathered[b * k..(b + 1) * k];
                let all: f64 = z.iter().zip(&self.share).map(|(z, s)| z * s).sum();
                for e in &self.entries[self.row[b]..self.row[b + 1]] {
                    let v = if e.d == ALL_CELLS { all } else { z[e.d as usize] };
                    mean[e.source as usize * self.stride + e.m as usize] += e.f * v;
                }
            }
        });
        self.pull_down(mean);
        let mean = &*mean;
        x.par_chunks_mut(k).zip(&self.leaf_position).zip(&self.send).for_each(|((x, &pos), s)| {
            x.iter_mut().zip(&mean[pos as usize * self.stride..]).for_each(|(x, m)| *x = s * m);
        });
    }

    /// Each node's value added to its children's by their area shares (a cluster's facing
    /// values by the child's shares of them, into an element spread by the cells' shares),
    /// parents before children: serial, over the nodes.
    fn pull_down(&self, mean: &mut [f64]) {
        let (k, stride) = (self.k, self.stride);
        for pos in 1..self.parent.len() {
            let (up, down) = mean.split_at_mut(pos * stride);
            let parent = &up[self.parent[pos] as usize * stride..][..stride];
            let child = &mut down[..stride];
            if !self.into_cluster[pos] {
                let w = self.weight[pos];
                child[..k].iter_mut().zip(&parent[..k]).for_each(|(c, p)| *c += w * p);
                continue;
            }
            let shares = self.facing_share[pos].iter().zip(parent.iter());
            match self.cluster[pos] {
                true => shares.zip(child.iter_mut()).for_each(|((s, p), c)| *c += s * p),
                false => {
                    let total: f64 = shares.map(|(s, p)| s * p).sum();
                    child[..k].iter_mut().zip(&self.share).for_each(|(c, s)| *c += s * total);
                }
            }
        }
    }
}

/// `lanes` ranges of the rows of the CSR offsets `row`, cut where their entries are about
/// equal in number: `lanes + 1` row indices (the first 0, the last the rows' number), then
/// the rows' number again.
fn balanced_cuts(row: &[usize], lanes: usize) -> [usize; MOST_LANES + 1] {
    let (rows, entries) = (row.len() - 1, row[row.len() - 1]);
    let mut cuts = [rows; MOST_LANES + 1];
    for (lane, cut) in cuts.iter_mut().enumerate().take(lanes).skip(1) {
        *cut = row.partition_point(|&r| r < entries * lane / lanes).min(rows);
    }
    cuts[0] = 0;
    cuts
}

/// `total` (zeroed first) as the sum of what `add` scatters from each range of items
/// between consecutive `cuts`, one task a range, the first into `total` itself and each
/// other into its own part of `spare` (as long as `total`), added at the end.
fn scattered(total: &mut [f64], spare: &mut [f64], cuts: &[usize], add: impl Fn(Range<usize>, &mut [f64]) + Sync) {
    let (n, lanes) = (total.len(), cuts.len() - 1);
    let mut parts: [Option<&mut [f64]>; MOST_LANES] = Default::default();
    let others = spare.chunks_mut(n.max(1)).take(lanes - 1);
    for (part, slice) in parts.iter_mut().zip(std::iter::once(&mut *total).chain(others)) {
        *part = Some(slice);
    }
    parts.par_iter_mut().enumerate().for_each(|(lane, part)| {
        if let Some(part) = part {
            part.fill(0.0);
            add(cuts[lane]..cuts[lane + 1], part);
        }
    });
    const BLOCK: usize = 1 << 12;
    let spare = &*spare;
    total.par_chunks_mut(BLOCK).enumerate().for_each(|(c, t)| {
        for lane in 1..lanes {
            let from = &spare[(lane - 1) * n + c * BLOCK..][..t.len()];
            t.iter_mut().zip(from).for_each(|(t, f)| *t += f);
        }
    });
}
