//! One more refinement pass (`docs/design.md` §3b, "Oracle"): with a solved field, every
//! link the oracle now rejects is refined, its receiver or source split.

use super::brightness::Brightness;
use super::kernel::{Hierarchy, cell_shares};
use super::refine::{Settings, Stopped, children_pairs, refine, split_node};
use crate::progress::Progress;
use std::time::Instant;

impl Hierarchy {
    /// One more pass with the field `x` of the current leaves (the order of
    /// [`Hierarchy::operator`]): every link the oracle now rejects is refined, with the
    /// readings' `importance` on the same unknowns if any (3b.3b). Returns the number of
    /// links refined (0: the hierarchy is final for this field), or why it stopped;
    /// `progress` hears of the pairs settled.
    pub fn refine(&mut self, x: &[f64], importance: Option<&[f64]>, progress: &dyn Progress) -> Result<usize, Stopped> {
        let start = Instant::now();
        let leaves = self.tree.leaves();
        let reflected = self.reflected(&leaves, x);
        let mean = self.mean_reflected(&leaves, &reflected);
        self.oracle.epsilon = self.options.tolerance * mean;
        let least = self.per_node(&leaves, reflected.iter().map(|r| r.max(0.0)), f64::INFINITY);
        let mut brightness = self.brightness(&leaves, x).with_gains(&self.tree, least, mean, self.options.dim_floor);
        if let Some(w) = importance.filter(|_| self.options.reading_weight > 0.0) {
            let k = self.directions.len();
            let per_leaf = (0..leaves.len()).map(|l| w[l * k..(l + 1) * k].iter().sum());
            let per_node = self.per_node(&leaves, per_leaf, 0.0);
            brightness = brightness.with_readings(&self.tree, per_node, self.options.reading_weight * mean);
        }
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
            partition: self.partition.as_ref(),
        };
        self.work.rays += refine(&mut self.tree, brightness, &settings, candidates, &mut self.links)?;
        Ok(())
    }

    /// Each leaf's `x − L0` (in `leaves` order), exitance-weighted over its cells, cd/m².
    fn reflected(&self, leaves: &[u32], x: &[f64]) -> Vec<f64> {
        let share = cell_shares(&self.directions);
        let k = share.len();
        let cells = |l: usize| x.get(l * k..(l + 1) * k).unwrap_or(&[]);
        let value = |l: usize| cells(l).iter().zip(&share).map(|(v, s)| v * s).sum::<f64>();
        leaves.iter().enumerate().map(|(l, &id)| value(l) - self.tree.node(id).emission).collect()
    }

    /// The area-weighted mean of the leaves' `reflected`, at least 0, cd/m².
    fn mean_reflected(&self, leaves: &[u32], reflected: &[f64]) -> f64 {
        let (mut sum, mut area) = (0.0, 0.0);
        for (&id, r) in leaves.iter().zip(reflected) {
            let exposed = self.tree.node(id).exposed;
            sum += exposed * r;
            area += exposed;
        }
        if area > 0.0 { (sum / area).max(0.0) } else { 0.0 }
    }

    /// One value per node: the leaves' `values` (in `leaves` order), `elsewhere` for the rest.
    fn per_node(&self, leaves: &[u32], values: impl Iterator<Item = f64>, elsewhere: f64) -> Vec<f64> {
        let mut out = vec![elsewhere; self.tree.len()];
        leaves.iter().zip(values).for_each(|(&id, v)| out[id as usize] = v);
        out
    }

    /// The brightest value of the leaf field `x` under every node (cd/m²), every gain 1.
    pub(super) fn brightness(&self, leaves: &[u32], x: &[f64]) -> Brightness {
        let k = self.directions.len();
        let largest =
            (0..leaves.len()).map(|l| x.get(l * k..(l + 1) * k).unwrap_or(&[]).iter().copied().fold(0.0, f64::max));
        Brightness::of(&self.tree, self.per_node(leaves, largest, 0.0))
    }
}
