//! The uniform kernel (`docs/design.md` §3): every facing pair of patches of one mesh
//! integrated (`pairs.rs`), the light by way of plane mirrors by their images (`images.rs`),
//! balanced to reciprocity and closure (`balance.rs`) and stored as one sparse `G` in double
//! or single precision (`matrix.rs`). It knows nothing of the hierarchy.

mod assembly;
mod balance;
mod images;
mod matrix;
mod pairs;

pub use assembly::{Assembled, assemble, row_stride};
pub use matrix::{Precision, TransportMatrix, spmv};
