//! A part's hierarchy rebuilt from the part files (issue 36, point 4; `docs/petsc.md`,
//! "The operator from the part files"): the roots and clusters as every process makes them,
//! every element any part's linking split (so the tree is the one-process linking's), and
//! the links that reach the part's leaves, those whose receiver overlaps it, each end found
//! by its address. Nothing is linked or refined again: the part then splits its leaves along
//! the light and writes its rows of the factors (`rows.rs`).

use super::address::Address;
use super::kernel::Hierarchy;
use super::link::Link;
use super::options::Options;
use super::pieces::Piece;
use super::tree::Tree;
use crate::directions::DirectionSet;
use crate::geometry::Mesh;
use crate::material::Block;
use crate::visibility::Visibility;

/// A link as a part file names it: its receiver's and source's addresses, its factor, its
/// visible fraction and its cell pieces.
pub type NamedLink<'a> = (&'a Address, &'a Address, f64, f32, &'a [Piece]);

impl Tree {
    /// The node at `address`, if the tree has it (`fresh`: the nodes before any split,
    /// which an address's `top` must be one of).
    fn at(&self, address: &Address, fresh: usize) -> Option<u32> {
        let top = address.top as usize;
        if top >= fresh || (!address.path.is_empty() && self.node(address.top).patch().is_none()) {
            return None;
        }
        address.path.iter().try_fold(address.top, |id, &c| self.children(id).get(c as usize).copied())
    }
}

impl Hierarchy {
    /// The hierarchy of part `options.part` over `roots` (as [`Hierarchy::new`] takes them)
    /// with every element of `splits` split and those of `links` whose receiver overlaps
    /// the part; an address the tree does not have is refused by name.
    #[allow(clippy::too_many_arguments)]
    pub fn rebuilt<'a>(
        roots: &Mesh,
        visibility: Visibility,
        directions: DirectionSet,
        blocks: Vec<Block>,
        options: Options,
        l0: &[f64],
        splits: &[Address],
        links: impl Iterator<Item = NamedLink<'a>>,
    ) -> Result<Hierarchy, String> {
        let (mut h, _) = Hierarchy::unlinked(roots, visibility, directions, blocks, options, l0);
        let partition = h.partition.clone().ok_or("a rebuilt hierarchy is one part's (Options::part)")?;
        let fresh = h.tree.len();
        let mut order: Vec<&Address> = splits.iter().collect();
        order.sort_by_key(|a| a.path.len());
        for address in order {
            let id = h.tree.at(address, fresh).ok_or_else(|| missing("split element", address))?;
            let Hierarchy { tree, backs, visibility, .. } = &mut h;
            tree.split(id, &|p| backs.exposed_area(visibility, p));
        }
        for (receiver, source, factor, visible, pieces) in links {
            let p = h.tree.at(receiver, fresh).ok_or_else(|| missing("link receiver", receiver))?;
            if !partition.overlaps(&h.tree, p) {
                continue;
            }
            let q = h.tree.at(source, fresh).ok_or_else(|| missing("link source", source))?;
            h.links.push(Link::new(p, q, factor, f64::from(visible), 0.0, pieces.to_vec()));
        }
        Ok(h)
    }
}

fn missing(what: &str, address: &Address) -> String {
    format!(
        "{what} at node {} and path {:?} is not in the tree the part files' splits make: parts of another linking?",
        address.top, address.path
    )
}
