//! What the oracle weighs a link's factor bound by (`docs/design.md` §3b, "Oracle", (3b.3)
//! and (3b.3a)): the brightest light under its source node, and its receiver's gain, how
//! many times finer than the scene's allowance its own is where its reflected light is dim
//! (3b.3a) or where the readings depend on it (3b.3b).

use super::node::NONE;
use super::tree::Tree;

/// Per node: the brightest light under it as a source, cd/m², and its gain as a receiver.
#[derive(Debug, Clone)]
pub struct Brightness {
    source: Vec<f64>,
    gain: Vec<f64>,
    /// The readings' importance under each node (`Σ W` over its leaves' unknowns), per
    /// cd/m², and what turns it into a gain.
    reading: Option<Reading>,
}

/// The readings' importance per node and the scale that turns it into a gain.
#[derive(Debug, Clone)]
struct Reading {
    importance: Vec<f64>,
    scale: f64,
}

impl Brightness {
    /// Every node's brightest leaf value (`largest`, one per node, leaves set) and gain 1.
    pub fn of(tree: &Tree, largest: Vec<f64>) -> Brightness {
        let source = up_the_tree(tree, largest, f64::max);
        let gain = vec![1.0; source.len()];
        Brightness { source, gain, reading: None }
    }

    /// The gains of the receivers, at least 1: `L̄ / max(min(L_p, L̄), floor · L̄)`, `L_p` the
    /// least reflected light under node `p` (`least`, one per node, leaves set), `L̄` the
    /// scene's mean.
    pub fn with_gains(mut self, tree: &Tree, least: Vec<f64>, mean: f64, floor: f64) -> Brightness {
        let least = up_the_tree(tree, least, f64::min);
        self.gain =
            least.iter().map(|&l| if mean > 0.0 { mean / l.min(mean).max(floor * mean) } else { 1.0 }).collect();
        self
    }

    /// The readings' gains (3b.3b): a receiver under which the readings' importance sums
    /// to `c` (per cd/m², `importance` one per node, leaves set) gains `scale · c` where
    /// that exceeds its gain from its dimness (`scale`: the readings' weight times `L̄`).
    pub fn with_readings(mut self, tree: &Tree, importance: Vec<f64>, scale: f64) -> Brightness {
        let importance = up_the_tree(tree, importance, |a, b| a + b);
        self.reading = Some(Reading { importance, scale });
        self
    }

    /// The weight of a link from `q` to `p`: `q`'s brightness times `p`'s gain, cd/m².
    pub fn weight(&self, p: u32, q: u32) -> f64 {
        self.source[q as usize] * self.gain(p as usize)
    }

    /// Receiver `p`'s gain: from its dimness, or from the readings where that is larger.
    fn gain(&self, p: usize) -> f64 {
        let dim = self.gain[p];
        match &self.reading {
            Some(r) => dim.max(r.scale * r.importance[p]),
            None => dim,
        }
    }

    /// New nodes of `tree` take their parent's values, the readings' importance by their
    /// share of its area.
    pub fn grow(&mut self, tree: &Tree) {
        for id in self.source.len()..tree.len() {
            let node = tree.node(id as u32);
            let parent = node.parent as usize;
            self.source.push(self.source[parent]);
            self.gain.push(self.gain[parent]);
            if let Some(r) = &mut self.reading {
                let share = node.area / tree.node(node.parent).area;
                r.importance.push(r.importance[parent] * share);
            }
        }
    }
}

/// `values` (one per node, the leaves' set) with every node's folded by `combine` into its
/// parent's, children before parents.
fn up_the_tree(tree: &Tree, mut values: Vec<f64>, combine: fn(f64, f64) -> f64) -> Vec<f64> {
    for id in tree.preorder().into_iter().rev() {
        let parent = tree.node(id).parent;
        if parent != NONE {
            values[parent as usize] = combine(values[parent as usize], values[id as usize]);
        }
    }
    values
}
