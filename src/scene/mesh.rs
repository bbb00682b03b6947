//! `shape = "mesh"`: a surface read from a mesh file, an OBJ (`obj.rs`) or a glTF 2.0 file
//! (`gltf.rs`, `.gltf` or `.glb`), scaled, rotated about any axis and translated, its
//! material groups given ugo materials (issue 17, item 3; issue 38, point 4;
//! `docs/scene-format.md`, "mesh").
//!
//! Every format takes the same path once loaded: a vertex `p` of the file (in a glTF file,
//! its nodes' transforms already applied) is placed at `R(axis, angle)·(scale·p) + translate`
//! (Rodrigues' rotation by `rotate_deg` about `rotate_axis`, counter-clockwise seen from the
//! tip of the axis), checked against the coordinate bound, its zero-area triangles dropped,
//! and the rest grouped by the ugo material they end up with, one part of the surface each.
//! Triangles of no material of the file take the surface's `material`; `materials =
//! { "name" = "ugo material" }` maps a material the file names, and every key of the table
//! must be one. An unmapped one with a colour (a glTF base colour) becomes a Lambert
//! material of its luminance (`crate::material::reflectance_of_colour`) named `FILE:name`;
//! one without (an OBJ `usemtl`) is an error naming it.

use super::check::{COORDINATE, ZERO_AREA, line, out_of_range};
use super::description::Material;
use super::error::SceneError;
use super::files::CaseFiles;
use super::loaded::Loaded;
use super::schema::RawSurface;
use super::shape_keys::{Part, ShapeKeys, material_index};
use crate::geometry::Shape;
use crate::material::{MaterialModel, reflectance_of_colour};
use glam::{DMat3, DVec3};
use std::path::Path;

/// The formats a mesh file is read in, by its extension (`.gltf` and `.glb` are glTF,
/// anything else OBJ).
#[derive(Clone, Copy)]
enum Format {
    Obj,
    Gltf,
}

impl Format {
    fn of(file: &Path) -> Format {
        let extension = file.extension().map(|e| e.to_string_lossy().to_ascii_lowercase());
        match extension.as_deref() {
            Some("gltf" | "glb") => Format::Gltf,
            _ => Format::Obj,
        }
    }

    fn noun(self) -> &'static str {
        match self {
            Format::Obj => "OBJ",
            Format::Gltf => "glTF",
        }
    }

    /// How the file gives its faces a material.
    fn naming(self) -> &'static str {
        match self {
            Format::Obj => "`usemtl`",
            Format::Gltf => "a primitive's `material`",
        }
    }

    /// The file loaded; `mapped` are the material names `materials` maps (a glTF file does
    /// not read their textures).
    fn load(self, file: &Path, files: &CaseFiles, mapped: &[&str]) -> Result<Loaded, String> {
        match self {
            Format::Obj => super::obj::load_obj(file, files),
            Format::Gltf => super::gltf::load_gltf(file, files, mapped),
        }
    }
}

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
    let format = Format::of(&file);
    let keys: Vec<&str> = s.materials.iter().flat_map(|t| t.get_ref().keys()).map(String::as_str).collect();
    let loaded = format.load(&file, k.files, &keys).map_err(|message| k.at.error("file", message))?;
    k.warnings.borrow_mut().extend(loaded.warnings.iter().map(|w| k.at.error("file", w.as_str())));
    let mapped = materials_of(k, s, format, name, &file, &loaded)?;
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

/// The ugo material of every group of `loaded` (group 0: the surface's `material`); `name`
/// is the file as the case names it.
fn materials_of(
    k: &ShapeKeys,
    s: &RawSurface,
    format: Format,
    name: &str,
    file: &Path,
    loaded: &Loaded,
) -> Result<Vec<usize>, SceneError> {
    let default = material_index(k.at, "material", &s.material, &k.materials.borrow())?;
    let empty = Default::default();
    let table = s.materials.as_ref().map_or(&empty, |t| t.get_ref());
    let at_line = || s.materials.as_ref().map_or(String::new(), |t| line(k.source, t));
    let (noun, shown) = (format.noun(), file.display());
    for key in table.keys() {
        if !loaded.groups.iter().any(|g| &g.name == key) {
            let known: Vec<String> = loaded.groups.iter().map(|g| format!("\"{}\"", g.name)).collect();
            let message = format!(
                "{}the {noun} file {shown} uses no material \"{key}\" ({}); its materials: {}",
                at_line(),
                format.naming(),
                if known.is_empty() { "none".to_string() } else { known.join(", ") }
            );
            return Err(k.at.error(&format!("materials.{key}"), message));
        }
    }
    let mut mapped = vec![default];
    for group in &loaded.groups {
        let index = match (table.get(&group.name), group.colour) {
            (Some(ugo), _) => material_index(k.at, &format!("materials.{}", group.name), ugo, &k.materials.borrow())?,
            (None, Some(colour)) => coloured(k, format!("{name}:{}", group.name), colour)?,
            (None, None) => {
                let message = format!(
                    "{}the {noun} file {shown} uses the material \"{}\" ({}), which `materials` does not map: add \
                     materials = {{ \"{}\" = \"<a [[material]]>\" }}",
                    at_line(),
                    group.name,
                    group.origin,
                    group.name
                );
                return Err(k.at.error("materials", message));
            }
        };
        mapped.push(index);
    }
    Ok(mapped)
}

/// The index of the Lambert material `name` that reflects the luminance of `colour`, added
/// to the case's materials the first time it is met (a file read by two surfaces, or an
/// array's copies, shares it).
fn coloured(k: &ShapeKeys, name: String, colour: [f64; 3]) -> Result<usize, SceneError> {
    let model = MaterialModel::Lambert { reflectance: reflectance_of_colour(colour), transmittance: 0.0 };
    let mut materials = k.materials.borrow_mut();
    match materials.iter().position(|m| m.name == name) {
        Some(index) if materials[index].model == model => Ok(index),
        Some(_) => {
            let message = format!(
                "a [[material]] is named \"{name}\", the name its base colour's material would take: rename it"
            );
            Err(k.at.error("file", message))
        }
        None => {
            materials.push(Material { name, model });
            Ok(materials.len() - 1)
        }
    }
}

fn zero_area([a, b, c]: &[DVec3; 3]) -> bool {
    let longest = (b - a).length().max((c - b).length()).max((a - c).length());
    (b - a).cross(c - a).length() / 2.0 <= ZERO_AREA * longest * longest
}
