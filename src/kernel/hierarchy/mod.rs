//! The hierarchical kernel of `docs/design.md` §3b (Hanrahan, Salzman & Aupperle 1991; clusters
//! after Smits, Arvo & Greenberg 1994 and Sillion 1995): element trees over a coarse mesh,
//! a cluster tree above them, links accepted by a brightness-weighted oracle, and `K x`
//! applied on the leaves by pull, gather and push. The uniform kernel is the special case
//! of all links between leaves.
//!
//! Use: `Hierarchy::new(&roots, directions, blocks, options, l0)` links the roots (a coarse
//! `Mesh`, with its source term); `iterate(&mut h, source, solve)` solves and refines in
//! passes; `h.operator()` is `K` on the leaves (a `LinOp`), `h.leaf_mesh()` the leaves'
//! mesh, `h.split_leaves(varies)` splits them along the luminaires' shadows.

mod balance;
mod census;
mod cluster;
mod expand;
mod history;
mod iterate;
mod kernel;
mod link;
mod node;
mod operator;
mod oracle;
mod push;
mod refine;
mod sight;
mod transpose;
mod tree;

pub use census::Census;
pub use history::Pass;
pub use iterate::{Iterated, Solver, SourceTerm, iterate};
pub use kernel::{DEFAULT_TOLERANCE, Hierarchy, Options};
pub use link::{ALL_CELLS, Link, Piece};
pub use node::{Kind, NONE, Node};
pub use operator::Operator;
pub use oracle::sample_points;
pub use push::SeenCache;
pub use sight::Sight;
pub use tree::Tree;
