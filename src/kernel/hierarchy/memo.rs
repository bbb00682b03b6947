//! What the hierarchy keeps from one operator to the next, in one value: each node's
//! closure rays (measured once, when it is first a leaf), the leaves' views of their ancestors' sources (`push.rs`),
//! and each node's balancing factors when it was last a balanced leaf, where the next
//! operator's balancing starts (`balance.rs`).

use super::node::NONE;
use super::push::SeenCache;
use super::tree::Tree;
use crate::transfer::closure::Closure;
use crate::transfer::exposure::Backs;
use crate::visibility::Visibility;
use rayon::prelude::*;

/// The caches of the hierarchy, by node id.
#[derive(Default)]
pub(super) struct Memo {
    /// Each node's closure rays (`transfer::closure`); `None` until it is a leaf of an
    /// operator.
    closure: Vec<Option<Closure>>,
    /// The leaves' views of their ancestors' sources, as the last operator's push found them.
    pub(super) seen: SeenCache,
    /// Each node's (receiving, sending) factors when it was last a balanced leaf.
    factors: Vec<Option<(f64, f64)>>,
}

impl Memo {
    /// Measures the closure of the `leaves` not yet measured; returns the rays taken. A
    /// signal's stop leaves the rest unmeasured (`crate::interrupt`: the caller checks).
    pub(super) fn measure_closure(
        &mut self,
        tree: &Tree,
        backs: &Backs,
        visibility: &Visibility,
        leaves: &[u32],
    ) -> usize {
        self.closure.resize(tree.len(), None);
        let todo: Vec<u32> = leaves.iter().copied().filter(|&id| self.closure[id as usize].is_none()).collect();
        let measured: Vec<Option<(Closure, usize)>> = todo
            .par_iter()
            .map(|&id| match tree.node(id).patch() {
                _ if crate::interrupt::asked() => None,
                Some(p) if p.exposed > 0.0 => Some(backs.closure(visibility, p)),
                _ => Some((Closure::default(), 0)),
            })
            .collect();
        todo.iter().zip(&measured).for_each(|(&id, m)| self.closure[id as usize] = m.map(|(c, _)| c));
        measured.iter().flatten().map(|m| m.1).sum()
    }

    /// The closure rays of node `id` (none cast if never measured).
    pub(super) fn closure(&self, id: u32) -> Closure {
        self.closure.get(id as usize).copied().flatten().unwrap_or_default()
    }

    /// The balancing factors node `id` had as a leaf of the last operator, else those of its
    /// nearest ancestor that was one (a leaf split since), else 1.
    pub(super) fn last_factors(&self, tree: &Tree, id: u32) -> (f64, f64) {
        let mut at = id;
        loop {
            if let Some(&Some(f)) = self.factors.get(at as usize) {
                return f;
            }
            match tree.node(at).parent {
                NONE => return (1.0, 1.0),
                parent => at = parent,
            }
        }
    }

    /// Keeps the factors of the balanced `leaves` (node ids, in leaf order).
    pub(super) fn keep_factors(&mut self, nodes: usize, leaves: &[u32], receive: &[f64], send: &[f64]) {
        self.factors.resize(nodes, None);
        for (l, &id) in leaves.iter().enumerate() {
            self.factors[id as usize] = Some((receive[l], send[l]));
        }
    }
}
