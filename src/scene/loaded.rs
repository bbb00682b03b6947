//! A mesh file as its reader returns it, whatever its format (`obj.rs`, `gltf.rs`): the
//! triangles in the file's frame, each with its material group, the groups, and what the
//! file holds that is not read; `mesh.rs` places them and gives the groups materials
//! (`docs/scene-format.md`, "mesh").

use glam::DVec3;

/// A mesh file as loaded, in its own frame.
pub(super) struct Loaded {
    /// Its triangles, each with its group: 0 for the surface's `material`, `g` for `groups[g - 1]`.
    pub triangles: Vec<(usize, [DVec3; 3])>,
    /// The materials the file names.
    pub groups: Vec<Group>,
    /// What the file holds that ugo does not read, said once per file.
    pub warnings: Vec<String>,
}

/// A material a mesh file names.
pub(super) struct Group {
    /// Its name, the key `materials` maps it by.
    pub name: String,
    /// Where the file names it (`usemtl` on its line 8, material #2), for messages.
    pub origin: String,
    /// The linear RGB colour the file gives it, taken when `materials` does not map it.
    pub colour: Option<[f64; 3]>,
}
