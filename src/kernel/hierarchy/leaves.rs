//! The hierarchy's current leaves as the unknowns see them: as a mesh, their own emission,
//! and a field of earlier leaves carried onto them.

use super::kernel::Hierarchy;
use super::node::{Kind, NONE};
use crate::geometry::{Mesh, NO_TWIN, Patch};

impl Hierarchy {
    /// The leaves as a mesh, in unknown order: each leaf (with its twin) its own face,
    /// twins paired, the surface's emission; usable by `Visibility`, the uniform assembly,
    /// probes and output.
    pub fn leaf_mesh(&self) -> Mesh {
        let leaves = self.tree.leaves();
        let mut index = vec![NONE; self.tree.len()];
        leaves.iter().enumerate().for_each(|(l, &id)| index[id as usize] = l as u32);
        let mut patches = Vec::with_capacity(leaves.len());
        let mut faces = 0u32;
        for (l, &id) in leaves.iter().enumerate() {
            let node = self.tree.node(id);
            let Some(&patch) = node.patch() else { continue };
            let twin = match node.kind {
                Kind::Element { twin, .. } if twin != NONE => index[twin as usize],
                _ => NO_TWIN,
            };
            let face = if twin != NO_TWIN && (twin as usize) < l {
                patches.get(twin as usize).map_or(faces, |p: &Patch| p.face)
            } else {
                faces += 1;
                faces - 1
            };
            patches.push(Patch { face, twin, ..patch });
        }
        let emission = leaves.iter().map(|&id| self.tree.node(id).emission).collect();
        Mesh { patches, emission, faces: faces as usize }
    }

    /// The leaves' own emission in every cell, cd/m² (`L0` without luminaires).
    pub fn emission(&self) -> Vec<f64> {
        let k = self.directions.len();
        self.tree.leaves().iter().flat_map(|&id| std::iter::repeat_n(self.tree.node(id).emission, k)).collect()
    }

    /// The field `x` on the leaves `old` (node ids, in the unknown order they had) carried
    /// onto the current leaves: each new leaf takes the value of the old leaf it lies in
    /// (refinement only splits).
    pub fn prolong(&self, old: &[u32], x: &[f64]) -> Vec<f64> {
        let k = self.directions.len();
        let mut index = vec![NONE; self.tree.len()];
        old.iter().enumerate().for_each(|(l, &id)| index[id as usize] = l as u32);
        let mut out = Vec::with_capacity(self.tree.len() * k);
        for id in self.tree.leaves() {
            let mut n = id;
            while n != NONE && index[n as usize] == NONE {
                n = self.tree.node(n).parent;
            }
            match (n != NONE).then(|| index[n as usize] as usize).and_then(|l| x.get(l * k..(l + 1) * k)) {
                Some(values) => out.extend_from_slice(values),
                None => out.extend(std::iter::repeat_n(0.0, k)),
            }
        }
        out
    }
}
