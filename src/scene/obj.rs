//! `shape = "mesh"`: a surface read from an OBJ file, scaled, rotated about any axis and
//! translated, its `usemtl` groups given ugo materials through the surface's `materials`
//! table (issue 17, item 3).
//!
//! A vertex `p` of the file is placed at `R(axis, angle)·(scale·p) + translate` (Rodrigues'
//! rotation by `rotate_deg` about `rotate_axis`, counter-clockwise seen from the tip of the
//! axis). Faces before any `usemtl` take the surface's `material`; every `usemtl` name of
//! the file must be mapped by `materials = { "objname" = "ugo material" }`, and every key of
//! the table must be a `usemtl` name of the file: either way the error names it. Triangles
//! are grouped by the ugo material they end up with, one part of the surface each.
//! The MTL files (`mtllib`) are not read: ugo's materials come from the case.

use super::check::{COORDINATE, ZERO_AREA, line, out_of_range};
use super::error::SceneError;
use super::schema::RawSurface;
use super::shape_keys::{Part, ShapeKeys, material_index};
use crate::geometry::Shape;
use glam::{DMat3, DVec3};
use std::path::Path;

/// The surface's parts: one `Shape::Mesh` per ugo material its triangles take.
pub(super) fn mesh(k: &ShapeKeys, s: &RawSurface) -> Result<Vec<Part>, SceneError> {
    let name = k.required("file", s.file.as_deref())?;
    if name.is_empty() {
        return Err(k.at.error("file", "must not be empty"));
    }
    let scale = k.at.positive("scale", s.scale.unwrap_or(1.0))?;
    let translate = k.at.place("translate", s.translate.unwrap_or([0.0; 3]))?;
    let axis = k.at.direction("rotate_axis", s.rotate_axis.unwrap_or([0.0, 1.0, 0.0]))?;
    let angle = k.at.finite("rotate_deg", s.rotate_deg.unwrap_or(0.0))?.to_radians();
    let rotation = DMat3::from_axis_angle(axis, angle);
    let file = k.at.file.parent().unwrap_or(Path::new("")).join(name);
    let loaded = load_obj(&file, k.files).map_err(|message| k.at.error("file", message))?;
    let mapped = materials_of(k, s, &file, &loaded)?;
    let place = |p: DVec3| rotation * (p * scale) + translate;
    let placed: Vec<(usize, [DVec3; 3])> = loaded.triangles.iter().map(|(g, t)| (mapped[*g], t.map(place))).collect();
    if placed.iter().flat_map(|(_, t)| t).any(|p| !p.is_finite()) {
        let message = format!("{} has a non-finite vertex (after scaling)", file.display());
        return Err(k.at.error("file", message));
    }
    if let Some(far) = placed.iter().flat_map(|(_, t)| t).find(|p| p.abs().max_element() > COORDINATE) {
        let got = format!(
            "the vertex [{:e}, {:e}, {:e}] of {}, scaled, rotated and translated",
            far.x,
            far.y,
            far.z,
            file.display()
        );
        return Err(k.at.error("scale", out_of_range(got)));
    }
    let mut parts: Vec<(usize, Vec<[DVec3; 3]>)> = Vec::new();
    for (material, triangle) in placed.into_iter().filter(|(_, t)| !zero_area(t)) {
        match parts.iter_mut().find(|(m, _)| *m == material) {
            Some((_, triangles)) => triangles.push(triangle),
            None => parts.push((material, vec![triangle])),
        }
    }
    if parts.is_empty() {
        let message = format!("all {} triangles of {} have zero area", loaded.triangles.len(), file.display());
        return Err(k.at.error("file", message));
    }
    let part =
        |(material, triangles)| Part { shape: Shape::Mesh { file: file.clone(), triangles }, material: Some(material) };
    Ok(parts.into_iter().map(part).collect())
}

/// The ugo material of every group of `loaded` (group 0: faces before any `usemtl`, the
/// surface's `material`).
fn materials_of(k: &ShapeKeys, s: &RawSurface, file: &Path, loaded: &Obj) -> Result<Vec<usize>, SceneError> {
    let default = material_index(k.at, "material", &s.material, k.materials)?;
    let empty = Default::default();
    let table = s.materials.as_ref().map_or(&empty, |t| t.get_ref());
    let at_line = || s.materials.as_ref().map_or(String::new(), |t| line(k.source, t));
    for key in table.keys() {
        if !loaded.names.iter().any(|(name, _)| name == key) {
            let known: Vec<String> = loaded.names.iter().map(|(n, _)| format!("\"{n}\"")).collect();
            let message = format!(
                "{}the OBJ file {} uses no material \"{key}\" (`usemtl`); its materials: {}",
                at_line(),
                file.display(),
                if known.is_empty() { "none".to_string() } else { known.join(", ") }
            );
            return Err(k.at.error(&format!("materials.{key}"), message));
        }
    }
    let mut mapped = vec![default];
    for (name, obj_line) in &loaded.names {
        let Some(ugo) = table.get(name) else {
            let message = format!(
                "{}the OBJ file {} uses the material \"{name}\" (`usemtl` on its line {obj_line}), which `materials` \
                 does not map: add materials = {{ \"{name}\" = \"<a [[material]]>\" }}",
                at_line(),
                file.display()
            );
            return Err(k.at.error("materials", message));
        };
        mapped.push(material_index(k.at, &format!("materials.{name}"), ugo, k.materials)?);
    }
    Ok(mapped)
}

/// An OBJ file as loaded: its triangles, each with its group (0 before any `usemtl`, `g`
/// for the `g`-th name of `names`), and the `usemtl` names with the line each first appears on.
struct Obj {
    triangles: Vec<(usize, [DVec3; 3])>,
    names: Vec<(String, usize)>,
}

/// The `mtllib` tobj is made to read: the `usemtl` names of the file, as materials.
const NAMES: &str = "ugo: the usemtl names";

/// The triangles of an OBJ file and its `usemtl` names; the error names the file.
fn load_obj(file: &Path, files: &super::files::CaseFiles) -> Result<Obj, String> {
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
    Ok(Obj { triangles, names })
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

fn zero_area([a, b, c]: &[DVec3; 3]) -> bool {
    let longest = (b - a).length().max((c - b).length()).max((a - c).length());
    (b - a).cross(c - a).length() / 2.0 <= ZERO_AREA * longest * longest
}
