//! One part of the hierarchy's links (issue 36, point 4; `docs/petsc.md`, "Parts"): the
//! roots, their seed light and the cluster tree as the one-process build makes them, then
//! the initial linking of the receivers of part `i` of `n` only (`hierarchy::Partition`),
//! each link named by its ends' addresses so that parts built apart join into the
//! one-process linking. Only that first linking: the passes after it refine against the
//! solved global field, and balancing needs the global columns, which no part has alone.

use super::fingerprint::Fnv;
use super::hierarchical::{Seed, options, seed};
use super::range::check_blocks;
use super::system::ModelError;
use crate::kernel::hierarchy::{Address, Hierarchy, Link, Node, Options, Part, Partition, Piece, Tree};
use crate::luminaire::Source;
use crate::material::Block;
use crate::progress::Progress;
use crate::scene::{Hierarchical, Scene};
use std::collections::HashSet;
use std::fmt::Write;
use std::time::Instant;

/// A link by its ends' addresses.
#[derive(Debug, Clone, PartialEq)]
pub struct PartLink {
    /// The node that gathers.
    pub receiver: Address,
    /// The node gathered from.
    pub source: Address,
    /// `F_pq` with visibility.
    pub factor: f64,
    /// The visible fraction in `factor`.
    pub visible: f32,
    /// The factor by cells (`d`, `m`, `F^{d,m}`); empty for one cell.
    pub pieces: Vec<Piece>,
}

/// The links part `part` owns, and what they cost.
#[derive(Debug, Clone)]
pub struct PartLinks {
    /// Which part of how many.
    pub part: Part,
    /// The case's roots.
    pub roots: usize,
    /// This part's roots (node ids, ascending).
    pub own_roots: Vec<u32>,
    /// FNV-1a hash of every root's part: parts of one partition share it.
    pub partition: u64,
    /// The links whose receiver this part owns.
    pub links: Vec<PartLink>,
    /// The elements its linking split (as receivers or sources): with every other part's,
    /// they make the one-process tree (`model::part_rows`).
    pub splits: Vec<Address>,
    /// Links whose source lies (partly) in other parts: their sources' values come from
    /// other ranks at every application.
    pub cut: usize,
    /// The distinct sources of the cut links.
    pub remote_sources: usize,
    /// Links whose receiver (a cluster) spans other parts too: the light it gathers is
    /// pushed to leaves of other parts at every application.
    pub spanning: usize,
    /// The nodes this part's tree grew to (its own elements and the sources it split).
    pub nodes: usize,
    /// Bytes the links take in ugo (32 a link and the cell pieces), and the tree.
    pub bytes: usize,
    /// Occlusion rays of the linking.
    pub rays: usize,
    /// Seconds of the linking (the roots' light not counted).
    pub seconds: f64,
}

/// The links of part `part` of the hierarchy of `scene` (its initial linking, as
/// `Hierarchy::new` makes it in one process); `progress` hears of the pairs settled.
pub fn link_part(
    scene: &Scene,
    parameters: Hierarchical,
    part: Part,
    progress: &dyn Progress,
) -> Result<PartLinks, ModelError> {
    let directions = scene.discretization.directions.set();
    let blocks: Vec<Block> = scene.materials.iter().map(|m| m.model.block(&directions)).collect();
    check_blocks(scene, &blocks, directions.len())?;
    let sources: Vec<Source> = scene.luminaires.iter().map(Source::of).collect();
    let Seed { roots, visibility, l0, .. } = seed(scene, parameters, &sources, &blocks, progress)?;
    let start = Instant::now();
    let part_options = Options { part: Some(part), ..options(scene, parameters) };
    let h = Hierarchy::new(&roots, visibility, directions, blocks, part_options, &l0, progress)?;
    let partition = h.partition().expect("a part's hierarchy has its partition");
    Ok(collect(&h, partition, roots.len(), start.elapsed().as_secs_f64()))
}

/// What part `partition.part()` of `h` owns, with its counts.
fn collect(h: &Hierarchy, partition: &Partition, roots: usize, seconds: f64) -> PartLinks {
    let tree = h.tree();
    let own: Vec<&Link> = h.links().iter().filter(|l| partition.owns(tree, l.receiver)).collect();
    let part = partition.part();
    let remote = |id: u32| partition.mask(tree, id) != 1 << part.index;
    let cut: Vec<u32> = own.iter().map(|l| l.source).filter(|&s| remote(s)).collect();
    let remote_sources = cut.iter().collect::<HashSet<_>>().len();
    let spanning = own.iter().filter(|l| remote(l.receiver)).count();
    let pieces: usize = own.iter().map(|l| l.pieces.len()).sum();
    let bytes = own.len() * size_of::<Link>() + pieces * size_of::<Piece>() + tree.len() * size_of::<Node>();
    PartLinks {
        part,
        roots,
        own_roots: (0..roots as u32).filter(|&r| partition.owns(tree, r)).collect(),
        partition: partition_hash(tree, partition, roots),
        links: own.iter().map(|l| by_address(tree, l)).collect(),
        splits: (0..tree.len() as u32)
            .filter(|&id| tree.node(id).patch().is_some() && !tree.node(id).is_leaf())
            .map(|id| tree.address(id))
            .collect(),
        cut: cut.len(),
        remote_sources,
        spanning,
        nodes: tree.len(),
        bytes,
        rays: h.work().rays,
        seconds,
    }
}

fn by_address(tree: &Tree, link: &Link) -> PartLink {
    PartLink {
        receiver: tree.address(link.receiver),
        source: tree.address(link.source),
        factor: link.factor,
        visible: link.visible,
        pieces: link.pieces.to_vec(),
    }
}

/// FNV-1a of the part count and every root's part, in root order.
fn partition_hash(tree: &Tree, partition: &Partition, roots: usize) -> u64 {
    let mut h = Fnv::default();
    let _ = write!(h, "{} parts:", partition.part().count);
    for r in 0..roots as u32 {
        let _ = write!(h, "{},", partition.owner(tree, r));
    }
    h.0
}
