//! The kernel `K = B·G` of `docs/design.md` §3: balanced assembly of `G` from the transfer
//! toolkit (`crate::transfer`), its storage, the material blocks `B`, the memory estimate
//! and its refusal, the operators (factored and explicit) that solvers apply, and the
//! hierarchical form of the same operator (`hierarchy/`, `docs/design.md` §3b).

mod assembly;
mod balance;
mod blocks;
mod forecast;
pub mod hierarchy;
mod matrix;
pub mod memory;
mod operator;
mod reciprocity;
mod transport;

pub use assembly::{Assembled, assemble, facing, row_stride};
pub use balance::BalanceReport;
pub use blocks::apply_blocks;
pub use forecast::{Forecast, OverLimit};
pub use matrix::{Precision, TransportMatrix, spmv};
pub use memory::{Estimate, Footprint, TooLarge};
pub use operator::{Explicit, Factored, Kernel};
pub use reciprocity::sent_shares;
pub use transport::Transport;
