//! Geometry: convex polygons, tessellation of shapes, and the patch mesh (`design.md` §2).

mod mesh;
mod polygon;
mod tessellate;

pub use mesh::{Mesh, Patch};
pub use polygon::{ConvexPolygon, MAX_CLIPPED};
pub use tessellate::tessellate;
