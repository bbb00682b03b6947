//! One part's rows of the hierarchy's factors (issue 36, point 4; `docs/petsc.md`, "The
//! operator from the part files"; `docs/design.md` §3b, "Apply K x"): the tree by
//! depth-first position (the pull `R`, the same in every part), the gather rows `Λ` of the
//! bundles its links make, and the push rows `P` of its own leaves, each bundle named by its
//! key (receiver's position, source class, lone source's position) so that the parts' bundles are numbered as the
//! one-process operator numbers them, by key. With them each leaf's closure rays, what
//! balancing needs (`balanced.rs`), which the part cannot do alone.

use super::balanced::SENDING;
use super::bundle::{Bundles, SourceClass};
use super::kernel::Hierarchy;
use super::link::Link;
use super::node::{FACING, NONE};
use super::operator::{facing_shares, gather_rows, parents};
use super::parts::Entry;
use super::push::push_rows;
use crate::progress::Progress;
use crate::transfer::closure::Closure;
use std::ops::Range;

/// A bundle by what orders it in the one-process operator: its receiver's depth-first
/// position, its sources' class and its lone source's position (`bundle.rs`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub struct BundleKey {
    /// Depth-first position of the receiver.
    pub receiver: u32,
    /// [`SourceClass::code`]: the sources' kind and facing.
    pub kind: u8,
    /// Depth-first position of its one source, [`ALL_SOURCES`](super::bundle::ALL_SOURCES) for a class of sources
    /// (`bundle.rs`).
    pub source: u32,
}

/// A part's rows of `G = P Λ R`, unbalanced.
#[derive(Debug, Clone)]
pub struct Rows {
    /// By depth-first position, the whole tree: parent ([`NONE`] at the top), area share in
    /// it, share of its facing areas under a cluster (`Parts::facing_share`), whether it is
    /// a cluster.
    pub parent: Vec<u32>,
    /// See `parent`.
    pub weight: Vec<f64>,
    /// See `parent`.
    pub facing_share: Vec<[f64; FACING]>,
    /// See `parent`.
    pub cluster: Vec<bool>,
    /// Tree node of every leaf, in unknown order.
    pub leaves: Vec<u32>,
    /// Depth-first position of every leaf.
    pub leaf_position: Vec<u32>,
    /// The part's leaves: a run of the unknowns.
    pub own_leaves: Range<usize>,
    /// The part's nodes: a run of depth-first positions (its roots' subtrees and the
    /// clusters it owns).
    pub own_nodes: Range<u32>,
    /// The part's bundles (those of the links it owns), by key, ascending: a run of the
    /// bundles, as its nodes are a run of the positions.
    pub bundles: Vec<BundleKey>,
    /// The gathered pieces of each of its bundles, CSR (sources by depth-first position).
    pub row: Vec<usize>,
    /// See `row`.
    pub entries: Vec<Entry>,
    /// Each own leaf's bundles and shares, CSR.
    pub push_row: Vec<usize>,
    /// See `push_row`.
    pub push: Vec<(BundleKey, f32)>,
    /// Each own leaf's closure rays.
    pub closure: Vec<Closure>,
    /// The links the part owns.
    pub links: usize,
    /// How far a sending factor may move from 1 (`balanced.rs`).
    pub sending: f64,
}

impl Hierarchy {
    /// The rows of the part this hierarchy was rebuilt for (`rebuilt.rs`) on its current
    /// leaves; the closure rays of its leaves count in the work; `progress` hears of the
    /// leaves whose push rows are done.
    pub fn part_rows(&mut self, progress: &dyn Progress) -> Result<Rows, String> {
        let partition = self.partition.clone().ok_or("rows are a part's (Options::part)")?;
        let tree = &self.tree;
        let order = tree.preorder();
        let mut position = vec![NONE; tree.len()];
        order.iter().enumerate().for_each(|(pos, &id)| position[id as usize] = pos as u32);
        let (parent, weight) = parents(tree, &order, &position);
        let cluster = order.iter().map(|&id| tree.node(id).patch().is_none()).collect();
        let facing_share = facing_shares(tree, &order);
        let leaves: Vec<u32> = order.iter().copied().filter(|&id| tree.node(id).is_leaf()).collect();
        let leaf_position = leaves.iter().map(|&id| position[id as usize]).collect();
        let own = |id: &u32| partition.owns(tree, *id);
        let own_leaves = run(&leaves, own).ok_or("the part's leaves are not one run of the unknowns")?;
        let nodes = run(&order, own).ok_or("the part's nodes are not one run of depth-first positions")?;
        let key = |links: &[Link], bundles: &Bundles, b: usize| BundleKey {
            receiver: position[bundles.receiver[b] as usize],
            kind: SourceClass::of(tree, &links[bundles.links_of(b)[0] as usize]).code(),
            source: bundles.source[b],
        };
        let reaching = Bundles::new(tree, &self.links, &position);
        let mine = &leaves[own_leaves.clone()];
        let (push_row, push) =
            push_rows(tree, &self.visibility, (&self.links, &reaching), mine, &mut self.memo.seen, progress);
        let push = push.into_iter().map(|(b, s)| (key(&self.links, &reaching, b as usize), s)).collect();
        // the part's own bundles: the run of those reaching it whose receiver it owns
        let Range { start: first, end } =
            run(&reaching.receiver, own).ok_or("the part's bundles are not one run of the bundles")?;
        let (all_rows, all_entries) = gather_rows(tree, &self.links, &reaching, &position);
        let row = all_rows[first..=end].iter().map(|r| r - all_rows[first]).collect();
        let entries = all_entries[all_rows[first]..all_rows[end]].to_vec();
        let keys = (first..end).map(|b| key(&self.links, &reaching, b)).collect();
        let links = (first..end).map(|b| reaching.links_of(b).len()).sum();
        let rays = self.memo.measure_closure(&self.tree, &self.backs, &self.visibility, mine);
        self.work.rays += rays;
        let closure = mine.iter().map(|&id| self.memo.closure(id)).collect();
        Ok(Rows {
            parent,
            weight,
            facing_share,
            cluster,
            leaves,
            leaf_position,
            own_leaves,
            own_nodes: nodes.start as u32..nodes.end as u32,
            bundles: keys,
            row,
            entries,
            push_row,
            push,
            closure,
            links,
            sending: SENDING * self.options.tolerance,
        })
    }
}

/// The run of `items` for which `own` holds, when they are one run (empty at the end when
/// none is).
fn run(items: &[u32], own: impl Fn(&u32) -> bool) -> Option<Range<usize>> {
    let first = items.iter().position(&own).unwrap_or(items.len());
    let end = first + items[first..].iter().take_while(|i| own(i)).count();
    items[end..].iter().all(|i| !own(i)).then_some(first..end)
}
