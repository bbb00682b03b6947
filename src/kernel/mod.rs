//! The kernel `K = B·G` of `design.md` §3: exact point-to-polygon form factors, adaptive
//! quadrature, visibility fractions, balanced assembly of `G`, material blocks `B`, and
//! the operators (factored and explicit) that solvers apply.

mod assembly;
mod balance;
pub mod contour;
pub mod form_factor;
pub mod hierarchy;
mod matrix;
pub mod memory;
pub mod occlusion;
mod operator;

pub use assembly::{Transport, assemble, facing};
pub use balance::BalanceReport;
pub use matrix::{Precision, TransportMatrix, spmv};
pub use memory::Estimate;
pub use operator::{Explicit, Factored, Kernel, LinOp};
