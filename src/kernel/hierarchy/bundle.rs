//! Bundles of links (`docs/design.md` (3b.5)): the links of one receiver
//! node from sources of one kind, gathered into one value and pushed to the receiver's leaves
//! with one set of shares (`push.rs`). A receiver's links from emitting elements form one
//! bundle and the rest another, so that each leaf takes the emitters' light by its own view
//! of the emitters, not by its view of everything its ancestor links to: under a node by a
//! wall and a block the leaves see the near faces very differently and the far lamp alike,
//! and one share for both moved a lamp's light by one leaf (the open box's floor by the
//! right wall read −15 … −19 % and the next column +11 … +34 %). The reflecting sources
//! are bundled apart by the way they face as well: the leaves of a node see the sources of
//! one plane in one ratio, which differs from plane to plane (the lowest leaves of a
//! block's side see the far floor in the ratio of their heights to their ancestor's, a
//! quarter, and the wall beside them as well as their ancestor does; in one bundle the
//! floor's light came at 0.8 of the ancestor's and they read 30 % bright,
//! `docs/hierarchy.md`, "Bundles by facing"). Those classes hold a leaf's own links and a
//! node's cluster sources: a link between elements whose receiver is not a leaf is a bundle
//! of its own, which each leaf takes by its own view of that one source, so that no bundle
//! hands a bright wall's light out by a dim armrest's view (`docs/hierarchy.md`, "A bundle
//! per source").

use super::link::Link;
use super::tree::Tree;

/// The kind of source a link gathers from: emitting elements are kept apart, and the other
/// sources near the receiver (closer than its own size) from those far from it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum SourceKind {
    /// An element that emits (a lamp surface): bright and small, seen alike by neighbours.
    Emitting,
    /// A reflecting node closer to the receiver than the receiver's diagonal: its leaves
    /// see it very differently.
    Near,
    /// Any other node: seen alike by the receiver's leaves.
    Far,
}

impl SourceKind {
    /// The kind of the link's source.
    pub fn of(tree: &Tree, link: &Link) -> SourceKind {
        let (p, q) = (tree.node(link.receiver), tree.node(link.source));
        if q.emission > 0.0 {
            SourceKind::Emitting
        } else if p.box_distance(q) < p.diagonal() {
            SourceKind::Near
        } else {
            SourceKind::Far
        }
    }
}

/// What a bundle's links share besides their receiver: the sources' kind and the way they
/// face.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub struct SourceClass {
    /// Emitting, near or far.
    pub kind: SourceKind,
    /// The axis and sign of the largest component of an element source's normal (0–5:
    /// +x, −x, +y, −y, +z, −z), 6 for a cluster.
    pub facing: u8,
}

impl SourceClass {
    /// The class of the link's source.
    pub fn of(tree: &Tree, link: &Link) -> SourceClass {
        let facing = match tree.node(link.source).patch() {
            Some(q) => {
                let axis = q.normal.abs().max_position();
                2 * axis as u8 + u8::from(q.normal[axis] < 0.0)
            }
            None => 6,
        };
        SourceClass { kind: SourceKind::of(tree, link), facing }
    }

    /// The class as one number, `8 × kind + facing` (emitting 0, near 1, far 2).
    pub fn code(self) -> u8 {
        8 * self.kind as u8 + self.facing
    }
}

/// Whether the leaves under the link's receiver see its source by their own rays, in a
/// bundle of its own (`push.rs`): an element source of a receiver that is not a leaf. A
/// cluster source's light, and a leaf's own links, are gathered with the links' own visible
/// fractions, in bundles of their class.
pub fn seen_by_leaves(tree: &Tree, link: &Link) -> bool {
    tree.node(link.source).patch().is_some() && !tree.node(link.receiver).is_leaf()
}

/// [`Bundles::source`] of a bundle of a class of sources: after every lone source of its
/// receiver and class.
pub const ALL_SOURCES: u32 = u32::MAX;

/// The links grouped into bundles, ordered by receiver (depth-first position) and source
/// class.
#[derive(Debug, Default)]
pub struct Bundles {
    /// Receiver node id of each bundle.
    pub receiver: Vec<u32>,
    /// The depth-first position of each bundle's one source (a link between elements whose
    /// receiver is not a leaf is a bundle of its own, `push.rs`), [`ALL_SOURCES`] for a
    /// bundle of a class of sources.
    pub source: Vec<u32>,
    /// The link indices of each bundle, CSR: `links[row[b]..row[b + 1]]`.
    pub row: Vec<usize>,
    pub links: Vec<u32>,
    /// By node id: its first bundle and how many it receives.
    by_node: Vec<(u32, u32)>,
}

impl Bundles {
    /// Groups `links` by receiver and source class, and the links between elements whose
    /// receiver is not a leaf one to a bundle; `position` is each node's depth-first position,
    /// which orders the bundles (by receiver, class and lone source), and the links within a
    /// bundle by source.
    pub fn new(tree: &Tree, links: &[Link], position: &[u32]) -> Bundles {
        let key = |l: u32| {
            let link = &links[l as usize];
            let source = if seen_by_leaves(tree, link) { position[link.source as usize] } else { ALL_SOURCES };
            (position[link.receiver as usize], SourceClass::of(tree, link), source)
        };
        // within a bundle by source: the same order however the links were made (a part's
        // links rebuilt from files, `rebuilt.rs`), so that the push's rays meet the same
        // last blocker first and its sums add alike
        let mut order: Vec<u32> = (0..links.len() as u32).collect();
        order.sort_unstable_by_key(|&l| (key(l), position[links[l as usize].source as usize]));
        let mut bundles = Bundles { row: vec![0], by_node: vec![(0, 0); tree.len()], ..Bundles::default() };
        for bundle in order.chunk_by(|&a, &b| key(a) == key(b)) {
            let receiver = links[bundle[0] as usize].receiver;
            let own = &mut bundles.by_node[receiver as usize];
            if own.1 == 0 {
                own.0 = bundles.receiver.len() as u32;
            }
            own.1 += 1;
            bundles.receiver.push(receiver);
            bundles.source.push(key(bundle[0]).2);
            bundles.row.push(bundles.row[bundles.row.len() - 1] + bundle.len());
        }
        bundles.links = order;
        bundles
    }

    /// Number of bundles.
    pub fn len(&self) -> usize {
        self.receiver.len()
    }

    /// The link indices of bundle `b`.
    pub fn links_of(&self, b: usize) -> &[u32] {
        &self.links[self.row[b]..self.row[b + 1]]
    }

    /// The bundles received by node `a`.
    pub fn of_node(&self, a: u32) -> std::ops::Range<usize> {
        let (first, count) = self.by_node[a as usize];
        first as usize..(first + count) as usize
    }
}
