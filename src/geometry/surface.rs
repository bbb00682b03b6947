//! What a surface is before meshing: its shape, its material, its sides and its emission
//! (`docs/design.md` §2, §7 `[[surface]]`). The scene file is validated into these; the mesh
//! is built from them.

use glam::DVec3;
use std::path::PathBuf;

/// Lambertian self-emission of a surface.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Emission {
    /// Luminance, cd/m², the same at every point and in every direction.
    Luminance(f64),
    /// Total luminous flux of the surface, lm, spread uniformly over its (meshed) area.
    Flux(f64),
}

/// `[[surface]]`: one named piece of geometry with its material.
#[derive(Debug, Clone)]
pub struct Surface {
    /// The surface's name, unique in the scene.
    pub name: String,
    /// Its geometry.
    pub shape: Shape,
    /// Index into the scene's materials.
    pub material: usize,
    /// Both sides reflect (and emit): meshed as two patches per element, back to back.
    pub two_sided: bool,
    /// Normals are flipped (a room seen from inside).
    pub inside: bool,
    /// Its own Lambertian emission, if it emits.
    pub emission: Option<Emission>,
}

/// The closed set of shapes. Lengths in metres, angles in degrees.
#[derive(Debug, Clone, PartialEq)]
pub enum Shape {
    /// Parallelogram `origin + s·edge_u + t·edge_v`, `s, t ∈ [0,1]`; normal `u × v`.
    Rectangle {
        /// The corner the edges start from, m.
        origin: DVec3,
        /// The first edge, m.
        edge_u: DVec3,
        /// The second edge, m.
        edge_v: DVec3,
    },
    /// Planar simple polygon, vertices counter-clockwise seen from the front.
    Polygon {
        /// The vertices, m.
        vertices: Vec<DVec3>,
    },
    /// Planar simple polygon less holes (a wall less its windows): `outline` counter-clockwise
    /// seen from the front, each hole a simple polygon in its plane, inside it, overlapping
    /// no other (the scene checks); meshed by `holes::holed_pieces`.
    Holed {
        /// The outer boundary, m.
        outline: Vec<DVec3>,
        /// The holes, each a polygon (either vertex order), m.
        holes: Vec<Vec<DVec3>>,
    },
    /// Axis-aligned box rotated about the vertical (y) axis through its centre; normals outward.
    Box {
        /// The lower corner before rotation, m.
        min: DVec3,
        /// The upper corner before rotation, m.
        max: DVec3,
        /// The turn about the vertical axis through the centre, degrees.
        rotate_y_deg: f64,
    },
    /// Flat disc facing `normal`.
    Disc {
        /// The centre, m.
        center: DVec3,
        /// The unit normal of the front.
        normal: DVec3,
        /// The radius, m.
        radius: f64,
    },
    /// Sphere with outward normals (tessellated into planar patches).
    Sphere {
        /// The centre, m.
        center: DVec3,
        /// The radius, m.
        radius: f64,
    },
    /// Triangles loaded from an OBJ or glTF file (already placed), normals by winding.
    Mesh {
        /// The OBJ or glTF file, as named (joined to the case file's folder).
        file: PathBuf,
        /// Its triangles in the scene, m.
        triangles: Vec<[DVec3; 3]>,
    },
}
