//! `[[surface]]` tables: shapes and their keys, emission, material references, degenerate
//! geometry, and loading `mesh` OBJ files, validated into `crate::geometry::Surface`.

use super::check::{COORDINATE, Context, MAGNITUDE, REL_TOL, ZERO_AREA, out_of_range, show, unique_names};
use super::description::Material;
use super::error::SceneError;
use super::files::CaseFiles;
use super::polygon::polygon_defect;
use super::schema::{RawEmission, RawSurface};
use crate::geometry::{Emission, Shape, Surface, tessellate};
use crate::material::MaterialModel;
use glam::DVec3;
use std::path::Path;

pub(super) fn surfaces(
    path: &Path,
    raw: &[RawSurface],
    materials: &[Material],
    files: &CaseFiles,
) -> Result<Vec<Surface>, SceneError> {
    unique_names(path, "surface", raw.iter().map(|s| s.name.as_str()))?;
    raw.iter()
        .enumerate()
        .map(|(index, s)| surface(&Context::item(path, "surface", &s.name, index), s, materials, files))
        .collect()
}

pub(super) fn emits(emission: Emission) -> bool {
    match emission {
        Emission::Luminance(x) | Emission::Flux(x) => x > 0.0,
    }
}

fn surface(at: &Context, s: &RawSurface, materials: &[Material], files: &CaseFiles) -> Result<Surface, SceneError> {
    let material = materials.iter().position(|m| m.name == s.material).ok_or_else(|| {
        let known: Vec<String> = materials.iter().map(|m| format!("\"{}\"", m.name)).collect();
        let message = format!("unknown material \"{}\"; known: {}", s.material, known.join(", "));
        at.error("material", message)
    })?;
    let two_sided = s.two_sided.unwrap_or(false);
    if let MaterialModel::Lambert { transmittance, .. } = materials[material].model
        && transmittance > 0.0
        && !two_sided
    {
        let message = format!("material \"{}\" transmits light, so the surface must be two_sided = true", s.material);
        return Err(at.error("two_sided", message));
    }
    let shape = shape(at, s, files)?;
    let area = meshable(at, &shape)?;
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
    Ok(Surface { name: s.name.clone(), shape, material, two_sided, inside: s.inside.unwrap_or(false), emission })
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
        Shape::Polygon { vertices } => ("shape", spread(vertices)),
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
type Build = fn(&ShapeKeys, &RawSurface) -> Result<Shape, SceneError>;

/// Every shape: its name, its keys, and its builder.
const SHAPES: [(&str, &[&str], Build); 6] = [
    ("rectangle", &["origin", "edge_u", "edge_v"], rectangle),
    ("polygon", &["vertices"], polygon),
    ("box", &["min", "max", "rotate_y_deg"], cuboid),
    ("disc", &["center", "normal", "radius"], disc),
    ("sphere", &["center", "radius"], sphere),
    ("mesh", &["file", "scale", "translate"], mesh),
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
    ]
    .into_iter()
    .filter_map(|(key, set)| set.then_some(key))
}

fn shape(at: &Context, s: &RawSurface, files: &CaseFiles) -> Result<Shape, SceneError> {
    let Some(&(name, keys, build)) = SHAPES.iter().find(|(name, ..)| *name == s.shape) else {
        let known: Vec<&str> = SHAPES.iter().map(|(name, ..)| *name).collect();
        let message = format!("unknown shape \"{}\"; known: {}", s.shape, known.join(", "));
        return Err(at.error("shape", message));
    };
    if let Some(stray) = shape_keys_set(s).find(|key| !keys.contains(key)) {
        let message = format!("not a key of shape \"{name}\" (its keys: {})", keys.join(", "));
        return Err(at.error(stray, message));
    }
    build(&ShapeKeys { at, shape: name, files }, s)
}

/// Reads the keys of one shape, reporting missing required ones.
struct ShapeKeys<'a> {
    at: &'a Context<'a>,
    shape: &'a str,
    /// Where a `mesh` reads its OBJ file.
    files: &'a CaseFiles,
}

impl ShapeKeys<'_> {
    fn required<T>(&self, key: &str, value: Option<T>) -> Result<T, SceneError> {
        let message = || format!("missing: shape \"{}\" needs `{key}`", self.shape);
        value.ok_or_else(|| self.at.error(key, message()))
    }

    fn point(&self, key: &str, value: Option<[f64; 3]>) -> Result<DVec3, SceneError> {
        self.at.place(key, self.required(key, value)?)
    }

    fn radius(&self, value: Option<f64>) -> Result<f64, SceneError> {
        self.at.length("radius", self.required("radius", value)?)
    }
}

fn rectangle(k: &ShapeKeys, s: &RawSurface) -> Result<Shape, SceneError> {
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
    Ok(Shape::Rectangle { origin, edge_u, edge_v })
}

fn polygon(k: &ShapeKeys, s: &RawSurface) -> Result<Shape, SceneError> {
    let raw = k.required("vertices", s.vertices.as_ref())?;
    let vertices = raw.iter().map(|&v| k.at.place("vertices", v)).collect::<Result<Vec<_>, _>>()?;
    polygon_defect(&vertices).map_err(|message| k.at.error("vertices", message))?;
    Ok(Shape::Polygon { vertices })
}

/// The `box` shape (`box` is a Rust keyword).
fn cuboid(k: &ShapeKeys, s: &RawSurface) -> Result<Shape, SceneError> {
    let min = k.point("min", s.min)?;
    let max = k.point("max", s.max)?;
    let rotate_y_deg = k.at.finite("rotate_y_deg", s.rotate_y_deg.unwrap_or(0.0))?;
    if !max.cmpgt(min).all() {
        let message = format!("must exceed `min` = {} on every axis, got {}", show(min), show(max));
        return Err(k.at.error("max", message));
    }
    Ok(Shape::Box { min, max, rotate_y_deg })
}

fn disc(k: &ShapeKeys, s: &RawSurface) -> Result<Shape, SceneError> {
    let center = k.point("center", s.center)?;
    let normal = k.at.direction("normal", k.required("normal", s.normal)?)?;
    let radius = k.radius(s.radius)?;
    Ok(Shape::Disc { center, normal, radius })
}

fn sphere(k: &ShapeKeys, s: &RawSurface) -> Result<Shape, SceneError> {
    let center = k.point("center", s.center)?;
    let radius = k.radius(s.radius)?;
    Ok(Shape::Sphere { center, radius })
}

/// `mesh`: loads the OBJ file (relative to the case file's folder), scales, translates,
/// and drops zero-area triangles.
fn mesh(k: &ShapeKeys, s: &RawSurface) -> Result<Shape, SceneError> {
    let name = k.required("file", s.file.as_deref())?;
    if name.is_empty() {
        return Err(k.at.error("file", "must not be empty"));
    }
    let scale = k.at.positive("scale", s.scale.unwrap_or(1.0))?;
    let translate = k.at.place("translate", s.translate.unwrap_or([0.0; 3]))?;
    let file = k.at.file.parent().unwrap_or(Path::new("")).join(name);
    let loaded = load_obj(&file, k.files).map_err(|message| k.at.error("file", message))?;
    let placed: Vec<[DVec3; 3]> = loaded.iter().map(|t| t.map(|p| p * scale + translate)).collect();
    if placed.iter().flatten().any(|p| !p.is_finite()) {
        let message = format!("{} has a non-finite vertex (after scaling)", file.display());
        return Err(k.at.error("file", message));
    }
    if let Some(far) = placed.iter().flatten().find(|p| p.abs().max_element() > COORDINATE) {
        let got =
            format!("the vertex [{:e}, {:e}, {:e}] of {}, scaled and translated", far.x, far.y, far.z, file.display());
        return Err(k.at.error("scale", out_of_range(got)));
    }
    let triangles: Vec<[DVec3; 3]> = placed.into_iter().filter(|t| !zero_area(t)).collect();
    if triangles.is_empty() {
        let message = format!("all {} triangles of {} have zero area", loaded.len(), file.display());
        return Err(k.at.error("file", message));
    }
    Ok(Shape::Mesh { file, triangles })
}

fn zero_area([a, b, c]: &[DVec3; 3]) -> bool {
    let longest = (b - a).length().max((c - b).length()).max((a - c).length());
    (b - a).cross(c - a).length() / 2.0 <= ZERO_AREA * longest * longest
}

/// The triangles of an OBJ file, as loaded; the error names the file.
fn load_obj(file: &Path, files: &CaseFiles) -> Result<Vec<[DVec3; 3]>, String> {
    let shown = file.display();
    let bytes = files.read(file).map_err(|e| format!("cannot open the OBJ file {shown}: {e}"))?;
    let options = tobj::LoadOptions { triangulate: true, single_index: true, ..Default::default() };
    // Materials of the OBJ file (`mtllib`) are not used: ugo's come from the case.
    let no_materials = |_: &Path| Err(tobj::LoadError::OpenFileFailed);
    let (models, _materials) = tobj::load_obj_buf(&mut bytes.as_slice(), &options, no_materials)
        .map_err(|e| format!("cannot read the OBJ file {shown}: {e}"))?;
    let mut triangles = Vec::new();
    for model in &models {
        let mesh = &model.mesh;
        let positions: Vec<DVec3> = mesh.positions.chunks_exact(3).map(|p| DVec3::new(p[0], p[1], p[2])).collect();
        for face in mesh.indices.chunks_exact(3) {
            let corner = |i: u32| positions.get(i as usize).copied();
            let (Some(a), Some(b), Some(c)) = (corner(face[0]), corner(face[1]), corner(face[2])) else {
                return Err(format!("the OBJ file {shown} has a vertex index out of range"));
            };
            triangles.push([a, b, c]);
        }
    }
    if triangles.is_empty() {
        return Err(format!("the OBJ file {shown} has no triangles"));
    }
    Ok(triangles)
}
