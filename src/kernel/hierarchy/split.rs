//! Leaves split along the light that arrives from outside the links (`docs/design.md` §3b,
//! "Sources"): the luminaires' shadow boundaries and the fall-off under them.

use super::kernel::Hierarchy;
use crate::geometry::Patch;
use crate::visibility::Visibility;
use rayon::prelude::*;

impl Hierarchy {
    /// Splits leaf elements, down to the smallest element size, while
    /// `varies(visibility, element, albedo, ε)` says that the light they receive from outside the links
    /// (the luminaires') changes over them by more than the error allowed (`ε`, cd/m²):
    /// their shadow boundaries. Links stay where they are (a split element is still covered
    /// by its ancestors' links). Returns the number of elements split.
    pub fn split_leaves(&mut self, varies: &(dyn Fn(&Visibility, &Patch, f64, f64) -> bool + Sync)) -> usize {
        let (patch_size, epsilon) = (self.options.patch_size, self.oracle.epsilon);
        let mut todo = self.tree.leaves();
        let mut splits = 0;
        while !todo.is_empty() {
            let (tree, visibility) = (&self.tree, &self.visibility);
            let chosen: Vec<u32> = todo
                .par_iter()
                .copied()
                .filter(|&id| {
                    let node = tree.node(id);
                    tree.can_split(id, patch_size)
                        && node.patch().is_some_and(|p| varies(visibility, p, node.albedo, epsilon))
                })
                .collect();
            todo.clear();
            for id in chosen {
                if !self.tree.node(id).is_leaf() {
                    continue; // the twin of an element split just before
                }
                let (visibility, backs) = (&self.visibility, &self.backs);
                self.tree.split(id, &|p| backs.exposed_area(visibility, p));
                splits += 1;
                todo.extend_from_slice(self.tree.children(id));
            }
        }
        self.work.splits += splits;
        splits
    }
}
