//! What the hierarchy is made of (`docs/design.md` §3b, for output and reports): each leaf's
//! level and root, and the links counted by the level they sit at and by their visibility.

use super::kernel::Hierarchy;
use super::link::Link;
use super::node::NONE;
use super::sight::Sight;
use super::structure::Skeleton;

/// Counts of the final hierarchy.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Census {
    /// Level of each leaf (unknown order; 0 = a root element).
    pub leaf_level: Vec<u8>,
    /// The root element (patch of the roots' mesh) each leaf lies in.
    pub leaf_root: Vec<u32>,
    /// Links between two elements, by the deeper level of the two.
    pub element_links: Vec<usize>,
    /// Links with a cluster at one end or both.
    pub cluster_links: usize,
    /// Links by visibility: every tested segment free, or some blocked.
    pub clear: usize,
    /// Links with some tested segment blocked.
    pub partial: usize,
}

impl Hierarchy {
    /// The census of the current leaves and links.
    pub fn census(&self) -> Census {
        Census::of(&self.tree().skeleton(), self.links(), &self.tree().leaves())
    }
}

impl Census {
    /// The census of the tree `skeleton` with its `links` and leaves `leaves` (node ids, in
    /// unknown order); a node id beyond the skeleton counts as a cluster.
    pub fn of(skeleton: &Skeleton, links: &[Link], leaves: &[u32]) -> Census {
        let Skeleton { parent, level } = skeleton;
        let level = |id: u32| level.get(id as usize).copied().flatten();
        let root = |mut id: u32| {
            while level(id).is_some_and(|l| l > 0) && parent.get(id as usize).is_some_and(|&p| p != NONE) {
                id = parent[id as usize];
            }
            id
        };
        let mut census = Census {
            leaf_level: leaves.iter().map(|&id| level(id).unwrap_or(0)).collect(),
            leaf_root: leaves.iter().map(|&id| root(id)).collect(),
            ..Census::default()
        };
        for link in links {
            match (level(link.receiver), level(link.source)) {
                (Some(a), Some(b)) => {
                    let deeper = a.max(b) as usize;
                    if census.element_links.len() <= deeper {
                        census.element_links.resize(deeper + 1, 0);
                    }
                    census.element_links[deeper] += 1;
                }
                _ => census.cluster_links += 1,
            }
            match link.sight() {
                Sight::Clear => census.clear += 1,
                _ => census.partial += 1,
            }
        }
        census
    }
}
