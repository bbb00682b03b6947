//! The hierarchy's tree without its geometry, and its links (`docs/design.md` §3b): what a
//! kernel file keeps of a hierarchy besides its operator (`parts.rs`) and its leaves' mesh
//! (`docs/kernel-file.md`, "The hierarchical kernel"), and what its census counts
//! (`census.rs`).

use super::kernel::Hierarchy;
use super::link::Link;
use super::node::Kind;
use super::tree::Tree;

/// Each node's parent ([`super::NONE`] at the top) and level below its root element
/// (`None` for a cluster), by node id.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Skeleton {
    /// The parent of each node.
    pub parent: Vec<u32>,
    /// The level of each node, `None` for a cluster.
    pub level: Vec<Option<u8>>,
}

impl Skeleton {
    /// The root element above node `id` (or `id` itself), or `None` when the walk up leaves
    /// the tree before meeting one (a cluster, or a skeleton read from a damaged file).
    pub fn root_of(&self, mut id: u32) -> Option<u32> {
        for _ in 0..=self.parent.len() {
            match self.level.get(id as usize)? {
                Some(0) => return Some(id),
                _ => id = *self.parent.get(id as usize)?,
            }
        }
        None
    }
}

/// The tree's skeleton, the links between its nodes and the roots' order.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Structure {
    /// The tree without geometry.
    pub skeleton: Skeleton,
    /// The links, by node id.
    pub links: Vec<Link>,
    /// By root element (node ids from 0), its position in the cluster tree's depth-first
    /// order ([`super::root_order`]), which decides its part (`partition.rs`); empty when
    /// read from a kernel file written before it was stored.
    pub root_position: Vec<u32>,
}

impl Structure {
    /// The position of each of the `leaves`' (node ids) root in the roots' depth-first
    /// order, or `None` when it is not known.
    pub fn leaf_root_positions(&self, leaves: &[u32]) -> Option<Vec<u32>> {
        leaves.iter().map(|&l| self.root_position.get(self.skeleton.root_of(l)? as usize).copied()).collect()
    }
}

impl Tree {
    /// The tree's parents and levels.
    pub fn skeleton(&self) -> Skeleton {
        let nodes = (0..self.len() as u32).map(|id| self.node(id));
        let (parent, level) = nodes
            .map(|n| {
                let level = match n.kind {
                    Kind::Element { level, .. } => Some(level),
                    Kind::Cluster => None,
                };
                (n.parent, level)
            })
            .unzip();
        Skeleton { parent, level }
    }
}

impl Hierarchy {
    /// The tree's skeleton and the links, the hierarchy given up for them.
    pub fn into_structure(self) -> Structure {
        let order = super::root_order(&self.tree);
        let mut root_position = vec![0; order.len()];
        for (j, &id) in order.iter().enumerate() {
            root_position[id as usize] = j as u32;
        }
        Structure { skeleton: self.tree.skeleton(), links: self.links, root_position }
    }
}
