//! The measurements of `ugo bench` (issue 9, `docs/performance.md`): what each figure times
//! and computes, returned as values that the command line prints and writes as JSON. The
//! occlusion rays through the default BVH (`occlusion.rs`) and through every layout
//! (`layouts.rs`); a STREAM-like triad against the sparse product `G x` and the factored
//! `K x` (`bandwidth.rs`); assembly and solve over patch sizes with the fitted growth
//! exponent, and the assembly's speed-up over threads (`scaling.rs`); the hierarchical
//! kernel's curve over leaf sizes (`hierarchy.rs`); the peak memory of one stretch of work
//! (`peak.rs`); dense LU in faer against nalgebra (`dense_lu.rs`); and the files `--export`
//! writes for the peers (`export.rs`). It prints nothing and parses no argument.

mod bandwidth;
mod dense_lu;
mod error;
mod export;
mod hierarchy;
mod layouts;
mod links;
mod occlusion;
mod pairs;
mod peak;
mod scaling;

pub use bandwidth::{SparseProduct, apply_seconds, sparse_product, triad};
pub use dense_lu::{DenseLu, dense_lu};
pub use error::BenchError;
pub use export::export;
pub use hierarchy::{Curve, Level, curve, level};
pub use layouts::{Layout, layouts};
pub use links::LinkRays;
pub use occlusion::{Occlusion, Segment};
pub use scaling::{Scaling, Step, assembly_with_threads, scaling, step};
