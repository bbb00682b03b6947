//! Solvers of `(I − K) x = L0` (`docs/design.md` §4): parameters in, info or a typed error out.
//!
//! Every method reports the same relative residual `‖L0 + Kx − x‖₂ / ‖L0‖₂` for every
//! iterate, the number of kernel applications and the wall time, so methods compare fairly.

mod algorithm;
mod arnoldi;
mod bicgstab;
mod direct;
mod gauss_seidel;
mod gmres;
mod history;
mod linop;
mod method;
mod neumann;
pub mod norms;
pub mod orders;
mod outcome;
mod range;
mod southwell;
mod successive;

pub use algorithm::Algorithm;
pub use arnoldi::{ArnoldiError, ArnoldiParams, Eigenpair, Spectrum, arnoldi};
pub use bicgstab::bicgstab;
pub use direct::{direct, direct_sparse};
pub use gauss_seidel::gauss_seidel;
pub use gmres::gmres;
pub use history::relative_residual;
pub use linop::LinOp;
pub use method::{Method, RESTART, System, solve};
pub use neumann::successive_approximation;
pub use outcome::{SolveError, SolveInfo, SolveParams};
pub use range::OutOfRange;
pub use southwell::southwell;
pub use successive::{Projection, Successive};
