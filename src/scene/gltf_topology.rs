//! The triangles of a glTF primitive's vertex order, by its mode (issue 38, point 4;
//! `docs/scene-format.md`, "glTF 2.0 meshes"): a list takes its vertices three by three; a
//! strip makes triangle `i` of vertices `i, i+1, i+2`, every odd one with its last two
//! swapped so that all keep the strip's orientation; a fan makes triangle `i` of vertices
//! `i+1, i+2, 0` around the first. The orders are those of the glTF 2.0 specification
//! (§3.7.2.1, "Topology Types"); other modes have no area.

use gltf::mesh::Mode;

/// Whether the primitives of `mode` have an area (triangles), not points or lines.
pub(super) fn has_area(mode: Mode) -> bool {
    matches!(mode, Mode::Triangles | Mode::TriangleStrip | Mode::TriangleFan)
}

/// The triangles of the vertex order `order` in `mode`, each as three entries of `order`
/// (none for points and lines). A list whose length is no multiple of 3, or a strip or fan
/// of fewer than 3 vertices, is an error.
pub(super) fn triangles(mode: Mode, order: &[usize]) -> Result<Vec<[usize; 3]>, String> {
    let n = order.len();
    let corners: Vec<[usize; 3]> = match mode {
        Mode::Triangles if !n.is_multiple_of(3) => return Err(format!("has {n} vertex indices, not a multiple of 3")),
        Mode::TriangleStrip | Mode::TriangleFan if n < 3 => {
            return Err(format!("is a {mode:?} of {n} vertices, fewer than 3"));
        }
        Mode::Triangles => (0..n / 3).map(|i| [3 * i, 3 * i + 1, 3 * i + 2]).collect(),
        Mode::TriangleStrip => (0..n - 2).map(|i| [i, i + 1 + i % 2, i + 2 - i % 2]).collect(),
        Mode::TriangleFan => (0..n - 2).map(|i| [i + 1, i + 2, 0]).collect(),
        Mode::Points | Mode::Lines | Mode::LineLoop | Mode::LineStrip => Vec::new(),
    };
    Ok(corners.into_iter().map(|t| t.map(|k| order[k])).collect())
}
