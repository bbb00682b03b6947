//! A node's address (issue 36, point 4): the root or cluster it descends from and the
//! child positions on the way down, the same in every process that builds the same roots,
//! whatever order its linking split them in, while node ids follow that order. The links
//! of parts built apart are compared and joined by their ends' addresses.

use super::node::Kind;
use super::tree::Tree;

/// Where a node lies in every tree over the same roots.
#[derive(Debug, Clone, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Address {
    /// The node id of the root element or cluster the node is or descends from (ids the
    /// tree's construction gives, before any split).
    pub top: u32,
    /// The child positions (0–3) from `top` down to the node.
    pub path: Vec<u8>,
}

impl Tree {
    /// The address of node `id`.
    pub fn address(&self, mut id: u32) -> Address {
        let mut path = Vec::new();
        while let Kind::Element { level, .. } = self.node(id).kind
            && level > 0
        {
            let parent = self.node(id).parent;
            let position = self.children(parent).iter().position(|&c| c == id);
            path.push(position.expect("a node is among its parent's children") as u8);
            id = parent;
        }
        path.reverse();
        Address { top: id, path }
    }
}
