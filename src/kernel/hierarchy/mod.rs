//! The hierarchical kernel of `docs/design.md` §3b (Hanrahan, Salzman & Aupperle 1991; clusters
//! after Smits, Arvo & Greenberg 1994 and Sillion 1995): element trees over a coarse mesh,
//! a cluster tree above them, links accepted by a brightness-weighted oracle, and `K x`
//! applied on the leaves by pull, gather and push. The uniform kernel is the special case
//! of all links between leaves.
//!
//! Use: `Hierarchy::new(&roots, visibility, directions, blocks, options, l0, progress)`
//! links the roots (a coarse `Mesh`, with its source term); `h.operator(progress)` is `G` on the
//! leaves, `h.leaf_mesh()` the leaves' mesh, `h.split_leaves(varies)` splits them along the
//! luminaires' shadows, `h.refine(x, progress)` refines again with a solved field (`progress`
//! hears of the pairs settled). `K = B·G` over it, and the passes
//! iterated with solves, are `crate::kernel::{Kernel, refine_with_solves}`: this module
//! knows neither the material blocks' product nor the uniform kernel.

mod address;
mod balance;
mod balanced;
mod brightness;
mod bundle;
mod census;
mod cluster;
mod cuts;
mod edges;
mod expand;
mod factors;
mod grading;
mod history;
mod kernel;
mod leaves;
mod link;
mod memo;
mod node;
mod openness;
mod operator;
mod options;
mod oracle;
mod partition;
mod parts;
mod pass;
mod pieces;
mod push;
mod rebuilt;
mod refine;
mod rows;
mod sight;
mod slots;
mod split;
mod structure;
mod transpose;
mod tree;
mod vector_areas;

pub use address::Address;
pub use balance::RULES as BALANCING_RULES;
pub use census::Census;
pub use factors::Factors;
pub use history::{Pass, Work};
pub use kernel::Hierarchy;
pub use link::{ALL_CELLS, Link};
pub use node::{FACING, Kind, NONE, Node, longest_edge};
pub use operator::Operator;
pub use options::{DEFAULT_PASSES, DEFAULT_TOLERANCE, Options};
pub use oracle::sample_points;
pub use partition::{BadPart, MOST_PARTS, Part, Partition, part_of, root_order};
pub use parts::{Entry, Parts};
pub use pieces::{Piece, Pieces};
pub use push::SeenCache;
pub use rebuilt::NamedLink;
pub use refine::Stopped;
pub use rows::{BundleKey, Rows};
pub use sight::Sight;
pub use structure::{Skeleton, Structure};
pub use tree::Tree;
