//! Hard probes placed by class (issue 34, point 1): point sensors drawn over the surfaces of
//! a case where solves are known to err (room corners and concave edges, contacts at the
//! feet of blocks, undersides, the floor under furniture, faces 2 cm apart, the umbrae and
//! penumbrae of the sources, the dimmest 5 %) and in the open as a control, each named by
//! its class (`corner-5cm/017`), so that a case plus the probes written out is a benchmark.
//!
//! Owns the classes (`class.rs`), the room's shell (`shell.rs`), what a point on a surface
//! sees along its normal and across its surface (`sight.rs`, `around.rs`), the moving of a
//! point along its surface to a distance from one or two walls (`settle.rs`), the share of
//! the direct light that reaches a point (`lights.rs`), the dimmest points by a quick
//! Monte Carlo estimate (`dim.rs`) and the drawing of candidates until every class is
//! full or the candidates run out (`place.rs`); and the same places for a mesh's leaves, for
//! the field's comparison leaf by leaf (`leaves.rs`). Everything is decided from the mesh and
//! ray casts, never per case, and depends only on the seed.

mod around;
mod class;
mod dim;
mod leaves;
mod lights;
mod place;
mod settle;
mod shell;
mod sight;

pub use around::OFFSET;
pub use class::{CONTACTS, Class, EDGES, Placed};
pub use leaves::{NEAR, Place, places};
pub use lights::{Lit, lit};
pub use place::{Options, Placement, place};
pub use shell::Shell;
