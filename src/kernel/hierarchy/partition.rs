//! The partition of the receivers (issue 36, point 4; `docs/petsc.md`, "Parts"): part `i`
//! of `n` holds the roots whose position in the cluster tree's depth-first order falls in
//! the `i`-th of `n` equal runs, so that it follows from the geometry alone (every part's
//! process builds the same roots and cluster tree) and, the cluster tree being median
//! splits, part boundaries follow its top clusters. An element lies in its root's part;
//! a cluster overlaps every part of its roots and belongs to the lowest. A part's linking
//! keeps only the candidate pairs whose receiver overlaps it ([`Partition::overlaps`]),
//! and its file only the links whose receiver belongs to it ([`Partition::owns`]). The rule
//! itself is [`root_order`] and [`part_of`], which a kernel file's per-leaf roots' positions
//! follow (`docs/kernel-file.md`), so that other programs find any leaf's part of any `n`.

use super::node::Kind;
use super::tree::Tree;

/// Most parts: a node's parts are a 64-bit mask.
pub const MOST_PARTS: u32 = 64;

/// Part `index` of `count`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Part {
    /// Which part, from 0.
    pub index: u32,
    /// How many parts.
    pub count: u32,
}

/// Why a `--part` value is refused.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum BadPart {
    /// Not two whole numbers `i/n`.
    #[error("{0:?}: expected i/n, two whole numbers such as 0/2 (part i of n, i from 0)")]
    Malformed(String),
    /// `n = 0`.
    #[error("{0}/0: the number of parts must be at least 1")]
    NoParts(u32),
    /// `i ≥ n`.
    #[error("{0}/{1}: the part index must be below the number of parts (0 to {max})", max = .1 - 1)]
    Beyond(u32, u32),
    /// `n` beyond [`MOST_PARTS`].
    #[error("{0}/{1}: at most {MOST_PARTS} parts")]
    TooMany(u32, u32),
}

impl std::str::FromStr for Part {
    type Err = BadPart;

    /// `i/n`, `0 ≤ i < n ≤` [`MOST_PARTS`].
    fn from_str(s: &str) -> Result<Part, BadPart> {
        let malformed = || BadPart::Malformed(s.to_string());
        let (i, n) = s.split_once('/').ok_or_else(malformed)?;
        let number = |t: &str| t.trim().parse::<u32>().map_err(|_| malformed());
        let (index, count) = (number(i)?, number(n)?);
        match (index, count) {
            (i, 0) => Err(BadPart::NoParts(i)),
            (i, n) if n > MOST_PARTS => Err(BadPart::TooMany(i, n)),
            (i, n) if i >= n => Err(BadPart::Beyond(i, n)),
            _ => Ok(Part { index, count }),
        }
    }
}

impl std::fmt::Display for Part {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}/{}", self.index, self.count)
    }
}

/// The root elements of `tree` in the cluster tree's depth-first order: a root's place in
/// it is what decides its part ([`part_of`]), and what a kernel file stores per leaf
/// (`/kernel/hierarchy/leaves/root_position`, `docs/kernel-file.md`).
pub fn root_order(tree: &Tree) -> Vec<u32> {
    let is_root = |id: &u32| matches!(tree.node(*id).kind, Kind::Element { level: 0, .. });
    tree.preorder().into_iter().filter(is_root).collect()
}

/// The part, of `count`, of the root at `position` in [`root_order`] of `roots` roots: the
/// `i`-th of `count` equal runs, `⌊position · count / roots⌋`.
pub fn part_of(position: u32, roots: usize, count: u32) -> u32 {
    (u64::from(position) * u64::from(count) / roots.max(1) as u64) as u32
}

/// Which parts each node of a tree's roots and clusters overlaps.
#[derive(Debug, Clone)]
pub struct Partition {
    part: Part,
    /// By node id, the roots and clusters (the nodes of a fresh tree): a bit per part.
    mask: Vec<u64>,
}

impl Partition {
    /// The partition of the fresh `tree` (roots and clusters only, nothing split yet).
    pub fn new(tree: &Tree, part: Part) -> Partition {
        let roots = root_order(tree);
        let mut mask = vec![0u64; tree.len()];
        for (j, &id) in roots.iter().enumerate() {
            mask[id as usize] = 1 << part_of(j as u32, roots.len(), part.count);
        }
        for id in tree.preorder().into_iter().rev() {
            let below = tree.children(id).iter().fold(0, |m, &c| m | mask[c as usize]);
            mask[id as usize] |= below;
        }
        Partition { part, mask }
    }

    /// The part this partition builds.
    pub fn part(&self) -> Part {
        self.part
    }

    /// The parts node `id` overlaps (a split element: its root's).
    pub fn mask(&self, tree: &Tree, mut id: u32) -> u64 {
        while id as usize >= self.mask.len() {
            id = tree.node(id).parent;
        }
        self.mask[id as usize]
    }

    /// True when some leaf under node `id` lies in this part.
    pub fn overlaps(&self, tree: &Tree, id: u32) -> bool {
        self.mask(tree, id) & (1 << self.part.index) != 0
    }

    /// The part node `id` belongs to: the lowest it overlaps.
    pub fn owner(&self, tree: &Tree, id: u32) -> u32 {
        self.mask(tree, id).trailing_zeros()
    }

    /// True when node `id` belongs to this part.
    pub fn owns(&self, tree: &Tree, id: u32) -> bool {
        self.owner(tree, id) == self.part.index
    }
}
