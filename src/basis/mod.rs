//! Kernel factorization in an angular basis (`docs/design.md` §4): real spherical and
//! hemispherical harmonics (`sh`), low-rank factors `ρ̄ ≈ Ψ Φᵀ` of the material blocks by
//! harmonics or by the truncated SVD (`factor`), and the reduced system for the basis
//! coefficients that every solver of the laboratory can solve (`reduced`).

mod factor;
mod reduced;
pub mod sh;

pub use factor::{Basis, BasisError, Factorization, MaterialFactor};
pub use reduced::Reduced;
