//! Geometry: surfaces as described, convex polygons, polygons with holes, rigid motions and
//! tessellation of shapes, the patch mesh (`docs/design.md` §2) and its section by a plane.

mod angle;
mod cut;
mod facing;
mod frame;
mod holes;
mod mesh;
mod motion;
mod polygon;
mod section;
mod surface;
mod tessellate;
mod warp;

pub use angle::angle;
pub use cut::{CUT_LEAST, Cut};
pub use facing::facing;
pub use frame::Frame;
pub use holes::{HoleFaults, hole_faults, holed_pieces};
pub use mesh::{Mesh, NO_TWIN, Patch};
pub use motion::Motion;
pub use polygon::{ConvexPolygon, MAX_CLIPPED};
pub use section::section;
pub use surface::{Emission, Shape, Surface};
pub use tessellate::{element_count, tessellate};
pub use warp::{cone, cosine_direction};
