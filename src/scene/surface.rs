//! `[[surface]]` tables: shapes and their keys, emission, material references and degenerate
//! geometry, validated into `crate::geometry::Surface` (a `mesh` is read by `mesh.rs`; one
//! whose file's groups take several materials becomes one surface per material).

use super::bounds::surfaces_bounds;
use super::check::{Context, MAGNITUDE, REL_TOL, show, unique_names};
use super::description::Material;
use super::error::SceneError;
use super::files::CaseFiles;
use super::holes::{Frame, holed};
use super::instances::copies;
use super::polygon::polygon_defect;
use super::schema::{RawEmission, RawSurface};
use super::shape_keys::{Part, ShapeKeys, material_index, whole};
use crate::geometry::{Emission, Shape, Surface, tessellate};
use crate::material::MaterialModel;
use glam::DVec3;
use std::cell::RefCell;
use std::collections::HashMap;
use std::path::Path;

/// Validates the `[[surface]]` tables of `path` (whose text is `source`): the surfaces (a
/// mesh whose file's groups take several materials is one per material) and, for each, the
/// index of its table. `materials` gains those made from mesh files' colours, `warnings`
/// what those files hold that is not read.
pub(super) fn surfaces(
    path: &Path,
    source: &str,
    raw: &[RawSurface],
    (materials, warnings): (&RefCell<Vec<Material>>, &RefCell<Vec<SceneError>>),
    files: &CaseFiles,
) -> Result<(Vec<Surface>, Vec<usize>), SceneError> {
    unique_names(path, "surface", raw.iter().map(|s| s.name.as_str()))?;
    let mut names: HashMap<String, usize> = raw.iter().enumerate().map(|(i, s)| (s.name.clone(), i)).collect();
    let (mut surfaces, mut tables) = (Vec::new(), Vec::new());
    for (index, s) in raw.iter().enumerate() {
        let at = Context::item(path, "surface", &s.name, index);
        let keys = ShapeKeys { at: &at, shape: "", files, materials, warnings, source };
        let parts = surface(&keys, s)?;
        let copies = copies(&at, source, s.array.as_ref(), s.transforms.as_ref(), centre(&parts))?;
        if copies.is_empty() {
            tables.extend(std::iter::repeat_n(index, parts.len()));
            surfaces.extend(parts);
            continue;
        }
        for copy in copies {
            for part in &parts {
                let shape = copy.motion.shape(&part.shape).ok_or_else(|| {
                    let message = "a box turns only about the vertical axis [0, 1, 0] (its faces stay vertical and \
                                   horizontal): give that axis, or model the box as a mesh";
                    at.error(&copy.key, message)
                })?;
                let name = format!("{}{}{}", s.name, copy.suffix, &part.name[s.name.len()..]);
                if let Some(other) = names.insert(name.clone(), index) {
                    let message =
                        format!("the copy \"{name}\" has the name of another surface ([[surface]] #{})", other + 1);
                    return Err(at.error("name", message));
                }
                surfaces.push(Surface { name, shape, ..part.clone() });
                tables.push(index);
            }
        }
    }
    Ok((surfaces, tables))
}

/// The centre of the surfaces' bounding box, m: the pivot of their copies' turns.
fn centre(parts: &[Surface]) -> DVec3 {
    let (low, high) = surfaces_bounds(parts);
    0.5 * (low + high)
}

pub(super) fn emits(emission: Emission) -> bool {
    match emission {
        Emission::Luminance(x) | Emission::Flux(x) => x > 0.0,
    }
}

/// The surface of table `s`, or one per material of its parts, named `NAME/material`.
fn surface(k: &ShapeKeys, s: &RawSurface) -> Result<Vec<Surface>, SceneError> {
    let at = k.at;
    let material = material_index(at, "material", &s.material, &k.materials.borrow())?;
    let two_sided = s.two_sided.unwrap_or(false);
    let parts = shape(k, s)?;
    let materials = k.materials.borrow();
    let areas = parts.iter().map(|p| meshable(at, &p.shape)).collect::<Result<Vec<f64>, _>>()?;
    let area: f64 = areas.iter().sum();
    for part in &parts {
        let index = part.material.unwrap_or(material);
        if let MaterialModel::Lambert { transmittance, .. } = materials[index].model
            && transmittance > 0.0
            && !two_sided
        {
            let name = &materials[index].name;
            let message = format!("material \"{name}\" transmits light, so the surface must be two_sided = true");
            return Err(at.error("two_sided", message));
        }
    }
    let emission = s.emission.as_ref().map(|e| emission(at, e)).transpose()?;
    if let Some(Emission::Flux(flux)) = emission
        && flux / (std::f64::consts::PI * area) > MAGNITUDE
    {
        let luminance = flux / (std::f64::consts::PI * area);
        let message = format!(
            "out of range: {flux:e} lm over the surface's {area:e} m² is a luminance of {luminance:e} cd/m², \
             more than {MAGNITUDE:e}"
        );
        return Err(at.error("emission.flux", message));
    }
    let single = parts.len() == 1;
    let surface = |(part, part_area): (Part, f64)| {
        let material = part.material.unwrap_or(material);
        let name = if single { s.name.clone() } else { format!("{}/{}", s.name, materials[material].name) };
        // A flux is shared by the parts in proportion to their areas.
        let emission = match emission {
            Some(Emission::Flux(flux)) if !single => Some(Emission::Flux(flux * part_area / area)),
            other => other,
        };
        Surface { name, shape: part.shape, material, two_sided, inside: s.inside.unwrap_or(false), emission }
    };
    Ok(parts.into_iter().zip(areas).map(surface).collect())
}

/// The shape meshes, at its coarsest, into patches of a total area that double precision
/// represents: a disc of radius 1e-300 (area 0) would otherwise vanish from the scene
/// with its emitted flux, and one of radius 1e200 (area ∞) poison every sum. Returns the
/// area, m².
fn meshable(at: &Context, shape: &Shape) -> Result<f64, SceneError> {
    let area: f64 = tessellate(shape, f64::INFINITY).iter().map(|e| e.area()).sum();
    if area.is_normal() {
        return Ok(area);
    }
    let (key, size) = match shape {
        Shape::Disc { radius, .. } | Shape::Sphere { radius, .. } => ("radius", *radius),
        Shape::Rectangle { edge_u, edge_v, .. } => ("shape", edge_u.length().max(edge_v.length())),
        Shape::Box { min, max, .. } => ("shape", (*max - *min).length()),
        Shape::Polygon { vertices } | Shape::Holed { outline: vertices, .. } => ("shape", spread(vertices)),
        Shape::Mesh { triangles, .. } => ("shape", spread(triangles.as_flattened())),
    };
    let why = if size > 1.0 { "too large" } else { "too small" };
    let message =
        format!("meshes to no patch: its area, {area:e} m², is {why} for double precision (lengths are in metres)");
    Err(at.error(key, message))
}

/// The largest distance of a point from the first, m (infinite on overflow).
fn spread(points: &[DVec3]) -> f64 {
    points.iter().map(|p| p.distance(points[0])).fold(0.0, f64::max)
}

/// `emission = { luminance = … }` or `{ flux = … }`: exactly one, finite and ≥ 0.
fn emission(at: &Context, raw: &RawEmission) -> Result<Emission, SceneError> {
    match (raw.luminance, raw.flux) {
        (Some(l), None) => {
            at.non_negative("emission.luminance", l)?;
            Ok(Emission::Luminance(at.magnitude("emission.luminance", l, " cd/m²")?))
        }
        (None, Some(f)) => {
            Ok(Emission::Flux(at.magnitude("emission.flux", at.non_negative("emission.flux", f)?, " lm")?))
        }
        (Some(_), Some(_)) => Err(at.error("emission", "give `luminance` or `flux`, not both")),
        (None, None) => Err(at.error("emission", "needs `luminance` (cd/m²) or `flux` (lm)")),
    }
}

/// Builds one shape from its keys.
type Build = fn(&ShapeKeys, &RawSurface) -> Result<Vec<Part>, SceneError>;

/// Every shape: its name, its keys, and its builder.
const SHAPES: [(&str, &[&str], Build); 6] = [
    ("rectangle", &["origin", "edge_u", "edge_v", "holes"], rectangle),
    ("polygon", &["vertices", "holes"], polygon),
    ("box", &["min", "max", "rotate_y_deg"], cuboid),
    ("disc", &["center", "normal", "radius"], disc),
    ("sphere", &["center", "radius"], sphere),
    ("mesh", &["file", "scale", "translate", "rotate_axis", "rotate_deg", "materials"], super::mesh::mesh),
];

/// The shape keys a `[[surface]]` sets.
fn shape_keys_set(s: &RawSurface) -> impl Iterator<Item = &'static str> {
    [
        ("origin", s.origin.is_some()),
        ("edge_u", s.edge_u.is_some()),
        ("edge_v", s.edge_v.is_some()),
        ("vertices", s.vertices.is_some()),
        ("min", s.min.is_some()),
        ("max", s.max.is_some()),
        ("rotate_y_deg", s.rotate_y_deg.is_some()),
        ("center", s.center.is_some()),
        ("normal", s.normal.is_some()),
        ("radius", s.radius.is_some()),
        ("file", s.file.is_some()),
        ("scale", s.scale.is_some()),
        ("translate", s.translate.is_some()),
        ("rotate_axis", s.rotate_axis.is_some()),
        ("rotate_deg", s.rotate_deg.is_some()),
        ("materials", s.materials.is_some()),
        ("holes", s.holes.is_some()),
    ]
    .into_iter()
    .filter_map(|(key, set)| set.then_some(key))
}

fn shape(k: &ShapeKeys, s: &RawSurface) -> Result<Vec<Part>, SceneError> {
    let Some(&(name, keys, build)) = SHAPES.iter().find(|(name, ..)| *name == s.shape) else {
        let known: Vec<&str> = SHAPES.iter().map(|(name, ..)| *name).collect();
        let message = format!("unknown shape \"{}\"; known: {}", s.shape, known.join(", "));
        return Err(k.at.error("shape", message));
    };
    if let Some(stray) = shape_keys_set(s).find(|key| !keys.contains(key)) {
        let message = format!("not a key of shape \"{name}\" (its keys: {})", keys.join(", "));
        return Err(k.at.error(stray, message));
    }
    build(&ShapeKeys { shape: name, ..*k }, s)
}

fn rectangle(k: &ShapeKeys, s: &RawSurface) -> Result<Vec<Part>, SceneError> {
    let origin = k.point("origin", s.origin)?;
    let edge_u = k.point("edge_u", s.edge_u)?;
    let edge_v = k.point("edge_v", s.edge_v)?;
    for (key, edge) in [("edge_u", edge_u), ("edge_v", edge_v)] {
        if edge == DVec3::ZERO {
            return Err(k.at.error(key, "must be a non-zero vector"));
        }
    }
    // Directions scaled first, so that a tiny (or huge) rectangle is not taken for a
    // parallel one when its squared lengths underflow (or overflow).
    let unit = |e: DVec3| (e / e.abs().max_element()).normalize();
    if unit(edge_u).cross(unit(edge_v)).length() <= REL_TOL {
        return Err(k.at.error("edge_v", "must not be parallel to `edge_u`"));
    }
    let Some(holes) = &s.holes else { return Ok(whole(Shape::Rectangle { origin, edge_u, edge_v })) };
    let frame = Frame { origin, edge_u, edge_v };
    Ok(whole(holed(k.at, k.source, frame.outline(), Some(frame), holes)?))
}

fn polygon(k: &ShapeKeys, s: &RawSurface) -> Result<Vec<Part>, SceneError> {
    let raw = k.required("vertices", s.vertices.as_ref())?;
    let vertices = raw.iter().map(|&v| k.at.place("vertices", v)).collect::<Result<Vec<_>, _>>()?;
    polygon_defect(&vertices).map_err(|message| k.at.error("vertices", message))?;
    match &s.holes {
        None => Ok(whole(Shape::Polygon { vertices })),
        Some(holes) => Ok(whole(holed(k.at, k.source, vertices, None, holes)?)),
    }
}

/// The `box` shape (`box` is a Rust keyword).
fn cuboid(k: &ShapeKeys, s: &RawSurface) -> Result<Vec<Part>, SceneError> {
    let min = k.point("min", s.min)?;
    let max = k.point("max", s.max)?;
    let rotate_y_deg = k.at.finite("rotate_y_deg", s.rotate_y_deg.unwrap_or(0.0))?;
    if !max.cmpgt(min).all() {
        let message = format!("must exceed `min` = {} on every axis, got {}", show(min), show(max));
        return Err(k.at.error("max", message));
    }
    Ok(whole(Shape::Box { min, max, rotate_y_deg }))
}

fn disc(k: &ShapeKeys, s: &RawSurface) -> Result<Vec<Part>, SceneError> {
    let center = k.point("center", s.center)?;
    let normal = k.at.direction("normal", k.required("normal", s.normal)?)?;
    let radius = k.radius(s.radius)?;
    Ok(whole(Shape::Disc { center, normal, radius }))
}

fn sphere(k: &ShapeKeys, s: &RawSurface) -> Result<Vec<Part>, SceneError> {
    let center = k.point("center", s.center)?;
    let radius = k.radius(s.radius)?;
    Ok(whole(Shape::Sphere { center, radius }))
}
