//! The kernel `K = B·G` of `docs/design.md` §3. Two peers build `G` and know nothing of
//! each other: the uniform kernel (`uniform/`: every facing pair of one mesh, stored) and
//! the hierarchical kernel (`hierarchy/`, §3b: links between elements at the levels its
//! oracle accepts, applied on the leaves). Below both: the material blocks `B`
//! (`blocks.rs`), what balancing reports (`balance_report.rs`), the one size estimate
//! (`forecast.rs`, `memory.rs`) and its one refusal (`refusal.rs`). Above both: `G` as
//! solvers see it (`transport.rs`), the one [`Kernel`] with its factored and explicit
//! operators (`operator.rs`), its reciprocity check (`reciprocity.rs`), and the hierarchy
//! refined with solves of that kernel (`refinement.rs`).

mod balance_report;
mod blocks;
mod closure_shares;
mod forecast;
pub mod hierarchy;
mod importance;
pub mod memory;
mod operator;
mod reciprocity;
mod refinement;
mod refusal;
mod transport;
mod uniform;

pub use balance_report::BalanceReport;
pub use blocks::apply_blocks;
pub use closure_shares::closure_shares;
pub use forecast::Forecast;
pub use importance::importance;
pub use memory::Footprint;
pub use operator::{Explicit, Factored, Kernel};
pub use reciprocity::sent_shares;
pub use refinement::{Readings, Refined, Solver, SourceTerm, refine_with_solves};
pub use refusal::{Need, TooLarge, figure};
pub use transport::Transport;
pub use uniform::{Assembled, Precision, TransportMatrix, assemble, row_stride, spmv};
