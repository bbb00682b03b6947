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

/// The tree's skeleton and the links between its nodes.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Structure {
    /// The tree without geometry.
    pub skeleton: Skeleton,
    /// The links, by node id.
    pub links: Vec<Link>,
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
        Structure { skeleton: self.tree.skeleton(), links: self.links }
    }
}
