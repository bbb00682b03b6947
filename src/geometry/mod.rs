//! Geometry: surfaces as described, convex polygons, tessellation of shapes, and the patch
//! mesh (`docs/design.md` §2).

mod facing;
mod frame;
mod mesh;
mod polygon;
mod surface;
mod tessellate;
mod warp;

pub use facing::facing;
pub use frame::Frame;
pub use mesh::{Mesh, NO_TWIN, Patch};
pub use polygon::{ConvexPolygon, MAX_CLIPPED};
pub use surface::{Emission, Shape, Surface};
pub use tessellate::{element_count, tessellate};
pub use warp::{cone, cosine_direction};
