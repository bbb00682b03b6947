//! One more refinement pass (`docs/design.md` §3b, "Oracle"): with a solved field, every
//! link the oracle now rejects is refined, its receiver or source split.

use super::kernel::{Hierarchy, cell_shares};
use super::node::NONE;
use super::refine::{Settings, Stopped, children_pairs, refine, split_node};
use crate::progress::Progress;
use std::time::Instant;

impl Hierarchy {
    /// One more pass with the field `x` of the current leaves (the order of
    /// [`Hierarchy::operator`]): every link the oracle now rejects is refined. Returns the
    /// number of links refined (0: the hierarchy is final for this field), or why it stopped;
    /// `progress` hears of the pairs settled.
    pub fn refine(&mut self, x: &[f64], progress: &dyn Progress) -> Result<usize, Stopped> {
        let start = Instant::now();
        let leaves = self.tree.leaves();
        self.oracle.epsilon = self.options.tolerance * self.mean_reflected(&leaves, x);
        let mut brightness = self.brightness(&leaves, x);
        let (mut redo, mut keep) = (Vec::new(), Vec::with_capacity(self.links.len()));
        for link in std::mem::take(&mut self.links) {
            let (p, q) = (link.receiver, link.source);
            let error = self.oracle.error(self.tree.node(p).albedo, f64::from(link.bound), brightness[q as usize]);
            match self.oracle.choose(&self.tree, p, q).filter(|_| self.oracle.refines(error)) {
                Some(n) => redo.push((p, q, n)),
                None => keep.push(link),
            }
        }
        self.links = keep;
        let mut candidates = Vec::with_capacity(4 * redo.len());
        let (visibility, backs) = (&self.visibility, &self.backs);
        for &(p, q, n) in &redo {
            split_node(&mut self.tree, &mut brightness, n, &|e| backs.exposed_area(visibility, e));
            children_pairs(&self.tree, p, q, n, &mut candidates);
        }
        self.refine_candidates(&mut brightness, candidates, progress)?;
        self.work.seconds += start.elapsed().as_secs_f64();
        Ok(redo.len())
    }

    /// Links the `candidates` pairs where the oracle accepts them, refining the rest;
    /// `progress` hears of the pairs settled.
    pub(super) fn refine_candidates(
        &mut self,
        brightness: &mut Vec<f64>,
        candidates: Vec<(u32, u32)>,
        progress: &dyn Progress,
    ) -> Result<(), Stopped> {
        let settings = Settings {
            visibility: &self.visibility,
            backs: &self.backs,
            oracle: self.oracle,
            quadrature: &self.options.quadrature,
            directions: &self.directions,
            memory_limit: self.options.memory_limit,
            progress,
        };
        self.work.rays += refine(&mut self.tree, brightness, &settings, candidates, &mut self.links)?;
        Ok(())
    }

    /// Area-weighted mean over the leaves of `x − L0` (exitance-weighted over cells), cd/m².
    fn mean_reflected(&self, leaves: &[u32], x: &[f64]) -> f64 {
        let share = cell_shares(&self.directions);
        let (mut sum, mut area) = (0.0, 0.0);
        for (l, &id) in leaves.iter().enumerate() {
            let node = self.tree.node(id);
            let cells = x.get(l * share.len()..(l + 1) * share.len()).unwrap_or(&[]);
            let value: f64 = cells.iter().zip(&share).map(|(v, s)| v * s).sum();
            sum += node.exposed * (value - node.emission);
            area += node.exposed;
        }
        if area > 0.0 { (sum / area).max(0.0) } else { 0.0 }
    }

    /// Largest value under every node of the leaf field `x` (cd/m²).
    pub(super) fn brightness(&self, leaves: &[u32], x: &[f64]) -> Vec<f64> {
        let k = self.directions.len();
        let mut b = vec![0.0; self.tree.len()];
        for (l, &id) in leaves.iter().enumerate() {
            let cells = x.get(l * k..(l + 1) * k).unwrap_or(&[]);
            b[id as usize] = cells.iter().copied().fold(0.0, f64::max);
        }
        for id in self.tree.preorder().into_iter().rev() {
            let parent = self.tree.node(id).parent;
            if parent != NONE {
                b[parent as usize] = f64::max(b[parent as usize], b[id as usize]);
            }
        }
        b
    }
}
