//! One more refinement pass (`docs/design.md` §3b, "Oracle"): with a solved field, every
//! link the oracle now rejects is refined, its receiver or source split.

use super::brightness::Brightness;
use super::kernel::{Hierarchy, cell_shares};
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
        let mean = self.mean_reflected(&leaves, x);
        self.oracle.epsilon = self.options.tolerance * mean;
        let least = self.least_reflected(&leaves, x);
        let mut brightness = self.brightness(&leaves, x).with_gains(&self.tree, least, mean, self.options.dim_floor);
        let (mut redo, mut keep) = (Vec::new(), Vec::with_capacity(self.links.len()));
        for link in std::mem::take(&mut self.links) {
            let (p, q) = (link.receiver, link.source);
            let error = self.oracle.error(self.tree.node(p).albedo, f64::from(link.bound), brightness.weight(p, q));
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
        brightness: &mut Brightness,
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
            sum += node.exposed * self.reflected(l, id, x, &share);
            area += node.exposed;
        }
        if area > 0.0 { (sum / area).max(0.0) } else { 0.0 }
    }

    /// Leaf `l`'s (node `id`'s) `x − L0`, exitance-weighted over its cells by `share`, cd/m².
    fn reflected(&self, l: usize, id: u32, x: &[f64], share: &[f64]) -> f64 {
        let cells = x.get(l * share.len()..(l + 1) * share.len()).unwrap_or(&[]);
        let value: f64 = cells.iter().zip(share).map(|(v, s)| v * s).sum();
        value - self.tree.node(id).emission
    }

    /// Each leaf's reflected light (`reflected`), infinite elsewhere, one per node, cd/m².
    fn least_reflected(&self, leaves: &[u32], x: &[f64]) -> Vec<f64> {
        let share = cell_shares(&self.directions);
        let mut least = vec![f64::INFINITY; self.tree.len()];
        for (l, &id) in leaves.iter().enumerate() {
            least[id as usize] = self.reflected(l, id, x, &share).max(0.0);
        }
        least
    }

    /// The brightest value of the leaf field `x` under every node (cd/m²), every gain 1.
    pub(super) fn brightness(&self, leaves: &[u32], x: &[f64]) -> Brightness {
        let k = self.directions.len();
        let mut b = vec![0.0; self.tree.len()];
        for (l, &id) in leaves.iter().enumerate() {
            let cells = x.get(l * k..(l + 1) * k).unwrap_or(&[]);
            b[id as usize] = cells.iter().copied().fold(0.0, f64::max);
        }
        Brightness::of(&self.tree, b)
    }
}
