//! `Gᵀ y` on the leaf unknowns: the hierarchy's transport (`operator.rs`, `docs/design.md` §3b
//! "Apply K x") run backwards, balancing factors included (`balance.rs`: `(R G S)ᵀ =
//! S Gᵀ R`). Push becomes a sum over each leaf's ancestors, gather a
//! scatter over the links from receiver to source, pull a sweep down the trees (into a
//! cluster: `Σ_d` of the cluster's value times each child cell's `μ_m/π`). Its uses: the
//! light each leaf sends to the whole scene, `Σ_i A_i G_ij` (the columns that energy
//! conservation constrains), and `‖K‖₁` without the expansion.

use super::link::ALL_CELLS;
use super::operator::{Operator, Scratch};

impl Operator {
    /// `x = Gᵀ y` (both `leaves × K`). Serial: it scatters. Nothing is allocated: it works in
    /// the operator's own arrays.
    pub fn leaving(&self, y: &[f64], x: &mut [f64]) {
        let k = self.k;
        let nodes = self.parent.len();
        let mut scratch = self.scratch.lock().unwrap_or_else(|e| e.into_inner());
        let Scratch { gathered, mean, .. } = &mut *scratch;
        gathered.fill(0.0);
        mean.fill(0.0);
        for (l, z) in y.chunks(k).enumerate() {
            for &(b, w) in &self.push[self.push_row[l]..self.push_row[l + 1]] {
                let g = &mut gathered[b as usize * k..][..k];
                let w = f64::from(w) * self.receive[l];
                g.iter_mut().zip(z).for_each(|(g, z)| *g += w * z);
            }
        }
        for (b, z) in gathered.chunks(k).enumerate() {
            let all: f64 = z.iter().zip(&self.share).map(|(z, s)| z * s).sum();
            for e in &self.entries[self.row[b]..self.row[b + 1]] {
                let v = if e.d == ALL_CELLS { all } else { z[e.d as usize] };
                mean[e.source as usize * k + e.m as usize] += e.f * v;
            }
        }
        for pos in 1..nodes {
            let (up, down) = mean.split_at_mut(pos * k);
            let parent = &up[self.parent[pos] as usize * k..][..k];
            let child = &mut down[..k];
            let w = self.weight[pos];
            if self.into_cluster[pos] {
                let total: f64 = parent.iter().sum();
                child.iter_mut().zip(&self.share).for_each(|(c, s)| *c += w * s * total);
            } else {
                child.iter_mut().zip(parent).for_each(|(c, p)| *c += w * p);
            }
        }
        for (l, &pos) in self.leaf_position.iter().enumerate() {
            let s = self.send[l];
            x[l * k..(l + 1) * k].iter_mut().zip(&mean[pos as usize * k..]).for_each(|(x, m)| *x = s * m);
        }
    }
}
