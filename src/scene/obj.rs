//! OBJ files as mesh surfaces (issue 17, item 3; `docs/scene-format.md`, "mesh"): the
//! faces, triangulated, each with its `usemtl` group (0 before any `usemtl`); the MTL files
//! (`mtllib`) are not read, the case maps the groups to its materials (`mesh.rs`).

use super::files::CaseFiles;
use super::loaded::{Group, Loaded};
use glam::DVec3;
use std::path::Path;

/// The `mtllib` tobj is made to read: the `usemtl` names of the file, as materials.
const NAMES: &str = "ugo: the usemtl names";

/// The triangles of an OBJ file and its `usemtl` groups; the error names the file.
pub(super) fn load_obj(file: &Path, files: &CaseFiles) -> Result<Loaded, String> {
    let shown = file.display();
    let bytes = files.read(file).map_err(|e| format!("cannot open the OBJ file {shown}: {e}"))?;
    let names = usemtl_names(&String::from_utf8_lossy(&bytes));
    let options = tobj::LoadOptions { triangulate: true, single_index: true, ..Default::default() };
    // tobj keeps a `usemtl` only for a material of a loaded MTL file: a first line makes it
    // "load" the names themselves; the file's own MTL files are not read.
    let mut text = format!("mtllib {NAMES}\n").into_bytes();
    text.extend_from_slice(&bytes);
    let as_materials = |path: &Path| -> tobj::MTLLoadResult {
        match path == Path::new(NAMES) {
            true => {
                let materials = names.iter().map(|(n, _)| tobj::Material { name: n.clone(), ..Default::default() });
                Ok((materials.collect(), names.iter().enumerate().map(|(i, (n, _))| (n.clone(), i)).collect()))
            }
            false => Ok(Default::default()),
        }
    };
    let (models, _) = tobj::load_obj_buf(&mut text.as_slice(), &options, as_materials)
        .map_err(|e| format!("cannot read the OBJ file {shown}: {e}"))?;
    let mut triangles = Vec::new();
    for model in &models {
        let mesh = &model.mesh;
        let group = mesh.material_id.map_or(0, |m| m + 1);
        let positions: Vec<DVec3> = mesh.positions.chunks_exact(3).map(|p| DVec3::new(p[0], p[1], p[2])).collect();
        for face in mesh.indices.chunks_exact(3) {
            let corner = |i: u32| positions.get(i as usize).copied();
            let (Some(a), Some(b), Some(c)) = (corner(face[0]), corner(face[1]), corner(face[2])) else {
                return Err(format!("the OBJ file {shown} has a vertex index out of range"));
            };
            triangles.push((group, [a, b, c]));
        }
    }
    if triangles.is_empty() {
        return Err(format!("the OBJ file {shown} has no triangles"));
    }
    let group =
        |(name, line): (String, usize)| Group { name, origin: format!("`usemtl` on its line {line}"), colour: None };
    Ok(Loaded { triangles, groups: names.into_iter().map(group).collect(), warnings: Vec::new() })
}

/// The distinct `usemtl` names of OBJ text, in order of first use, with that line (from 1),
/// read as tobj reads them (the rest of the line after the first space, trimmed).
fn usemtl_names(text: &str) -> Vec<(String, usize)> {
    let mut names: Vec<(String, usize)> = Vec::new();
    for (number, line) in text.lines().enumerate() {
        if line.split_whitespace().next() != Some("usemtl") {
            continue;
        }
        let name = line.split_once(' ').unwrap_or_default().1.trim();
        if !name.is_empty() && !names.iter().any(|(n, _)| n == name) {
            names.push((name.to_string(), number + 1));
        }
    }
    names
}
