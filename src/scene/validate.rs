//! Checks the raw tables of a case file and builds the runtime [`Scene`].
//!
//! Owns every rule of `design.md` §7 that serde cannot express: finite numbers, ranges,
//! defaults, unique names, material references, which keys belong to which shape,
//! degenerate geometry, and loading `mesh` OBJ files. Each failure is a [`SceneError`]
//! naming the table (`[[surface]] "floor" (#3)`) and the key.

use super::schema::{
    RawCamera, RawDirections, RawDiscretization, RawEmission, RawMaterial, RawProbe, RawScene, RawSceneInfo, RawSolver,
    RawSurface,
};
use super::{
    Camera, Discretization, Emission, Material, MaterialModel, Probe, Scene, SceneError, Shape, SolverSettings, Surface,
};
use crate::directions::DirectionSet;
use crate::solve::Method;
use glam::DVec3;
use std::path::Path;

/// Relative tolerance (to the shape's size) of the planarity, collinearity,
/// coincidence and parallel-edge tests.
pub(super) const REL_TOL: f64 = 1e-6;

/// An area below this fraction of (size)² counts as zero.
const ZERO_AREA: f64 = 1e-12;

/// Validates the raw tables of the case file `path` (whose text is `source`).
pub fn validate(path: &Path, source: String, raw: RawScene) -> Result<Scene, SceneError> {
    let (name, description) = scene_info(path, raw.scene);
    let discretization = discretization(path, raw.discretization)?;
    let solver = solver(path, raw.solver)?;
    if raw.surface.is_empty() {
        return Err(SceneError::new(path, "[[surface]]", "", "the scene has no [[surface]]"));
    }
    let materials = materials(path, &raw.material)?;
    let surfaces = surfaces(path, &raw.surface, &materials)?;
    let probes = probes(path, &raw.probe)?;
    let cameras = cameras(path, &raw.camera)?;
    let grids = super::grid::grids(path, &raw.grid)?;
    let luminaires = super::luminaire::luminaires(path, &raw.luminaire)?;
    if luminaires.is_empty() && !surfaces.iter().any(|s| s.emission.is_some_and(emits)) {
        let message = "nothing emits light: give a [[surface]] an `emission` greater than 0, or add a [[luminaire]]";
        return Err(SceneError::new(path, "", "emission", message));
    }
    Ok(Scene {
        path: path.to_path_buf(),
        source,
        name,
        description,
        discretization,
        solver,
        materials,
        surfaces,
        probes,
        cameras,
        grids,
        luminaires,
    })
}

/// Where a value sits: the case file and the table being validated.
pub(super) struct Context<'a> {
    pub(super) file: &'a Path,
    table: String,
}

impl<'a> Context<'a> {
    fn new(file: &'a Path, table: impl Into<String>) -> Self {
        Context { file, table: table.into() }
    }

    /// The context of the `index`-th (0-based) `[[kind]]` table, named `name`.
    pub(super) fn item(file: &'a Path, kind: &str, name: &str, index: usize) -> Self {
        Context::new(file, format!("[[{kind}]] \"{name}\" (#{})", index + 1))
    }

    pub(super) fn error(&self, key: &str, message: impl Into<String>) -> SceneError {
        SceneError::new(self.file, self.table.clone(), key, message)
    }

    pub(super) fn finite(&self, key: &str, x: f64) -> Result<f64, SceneError> {
        match x.is_finite() {
            true => Ok(x),
            false => Err(self.error(key, format!("must be a finite number, got {x}"))),
        }
    }

    pub(super) fn positive(&self, key: &str, x: f64) -> Result<f64, SceneError> {
        match self.finite(key, x)? > 0.0 {
            true => Ok(x),
            false => Err(self.error(key, format!("must be greater than 0, got {x}"))),
        }
    }

    fn non_negative(&self, key: &str, x: f64) -> Result<f64, SceneError> {
        match self.finite(key, x)? >= 0.0 {
            true => Ok(x),
            false => Err(self.error(key, format!("must be at least 0, got {x}"))),
        }
    }

    pub(super) fn point(&self, key: &str, v: [f64; 3]) -> Result<DVec3, SceneError> {
        let p = DVec3::from_array(v);
        match p.is_finite() {
            true => Ok(p),
            false => Err(self.error(key, format!("must have finite coordinates, got {}", show(p)))),
        }
    }

    /// A non-zero vector, normalized.
    pub(super) fn direction(&self, key: &str, v: [f64; 3]) -> Result<DVec3, SceneError> {
        let d = self.point(key, v)?;
        d.try_normalize().ok_or_else(|| self.error(key, format!("must be a non-zero vector, got {}", show(d))))
    }
}

/// `[x, y, z]` as written in TOML.
pub(super) fn show(v: DVec3) -> String {
    format!("[{}, {}, {}]", v.x, v.y, v.z)
}

/// `[scene]`: the name (default: the file stem) and the description (default empty).
fn scene_info(path: &Path, info: Option<RawSceneInfo>) -> (String, String) {
    let info = info.unwrap_or(RawSceneInfo { name: None, description: None });
    let stem = || path.file_stem().map(|s| s.to_string_lossy().into_owned());
    let name = info.name.or_else(stem).unwrap_or_default();
    (name, info.description.unwrap_or_default())
}

fn discretization(path: &Path, raw: Option<RawDiscretization>) -> Result<Discretization, SceneError> {
    let at = Context::new(path, "[discretization]");
    let raw = raw.ok_or_else(|| at.error("", "the table [discretization] is required"))?;
    let patch_size = at.positive("patch_size", raw.patch_size)?;
    let directions = match raw.directions {
        None => "1".to_string(),
        Some(RawDirections::Count(k)) => k.to_string(),
        Some(RawDirections::Name(name)) => name,
    };
    if DirectionSet::named(&directions).is_none() {
        let message =
            format!("unknown direction set \"{directions}\"; give a cell count ≥ 1, \"klems\" or \"tregenza\"");
        return Err(at.error("directions", message));
    }
    Ok(Discretization { patch_size, directions })
}

fn solver(path: &Path, raw: Option<RawSolver>) -> Result<SolverSettings, SceneError> {
    let at = Context::new(path, "[solver]");
    let default = SolverSettings::default();
    let Some(raw) = raw else { return Ok(default) };
    let tolerance = at.finite("tolerance", raw.tolerance.unwrap_or(default.tolerance))?;
    if tolerance <= 0.0 || tolerance >= 1.0 {
        let message = format!("must be greater than 0 and less than 1, got {tolerance}");
        return Err(at.error("tolerance", message));
    }
    let max_iterations = match raw.max_iterations {
        None => default.max_iterations,
        Some(n) => usize::try_from(n)
            .ok()
            .filter(|&n| n >= 1)
            .ok_or_else(|| at.error("max_iterations", format!("must be at least 1, got {n}")))?,
    };
    let method = raw.method.unwrap_or(default.method);
    if Method::parse(&method).is_none() {
        let message = format!("unknown method \"{method}\"; known: {}", Method::NAMES);
        return Err(at.error("method", message));
    }
    Ok(SolverSettings { method, tolerance, max_iterations })
}

/// Names must be non-empty and unique among the `[[kind]]` tables.
pub(super) fn unique_names<'n>(
    path: &Path,
    kind: &str,
    names: impl Iterator<Item = &'n str>,
) -> Result<(), SceneError> {
    let mut seen: Vec<&str> = Vec::new();
    for (index, name) in names.enumerate() {
        let at = Context::item(path, kind, name, index);
        if name.is_empty() {
            return Err(at.error("name", "must not be empty"));
        }
        if let Some(first) = seen.iter().position(|&s| s == name) {
            let message = format!("duplicate name \"{name}\" (also [[{kind}]] #{})", first + 1);
            return Err(at.error("name", message));
        }
        seen.push(name);
    }
    Ok(())
}

fn materials(path: &Path, raw: &[RawMaterial]) -> Result<Vec<Material>, SceneError> {
    if raw.is_empty() {
        let message = "the scene has no [[material]]";
        return Err(SceneError::new(path, "[[material]]", "", message));
    }
    unique_names(path, "material", raw.iter().map(|m| m.name.as_str()))?;
    let material = |(index, m): (usize, &RawMaterial)| {
        let at = Context::item(path, "material", &m.name, index);
        Ok(Material { name: m.name.clone(), model: material_model(&at, m)? })
    };
    raw.iter().enumerate().map(material).collect()
}

/// Keys each material type takes (the first is required where noted below).
const MATERIAL_KEYS: [(&str, &[&str]); 4] = [
    ("lambert", &["reflectance", "transmittance"]),
    ("phong", &["reflectance", "specular", "exponent"]),
    ("mirror", &["reflectance"]),
    ("ggx", &["reflectance", "specular", "roughness"]),
];

fn material_model(at: &Context, m: &RawMaterial) -> Result<MaterialModel, SceneError> {
    let Some((_, keys)) = MATERIAL_KEYS.iter().find(|(name, _)| *name == m.model) else {
        let known: Vec<String> = MATERIAL_KEYS.iter().map(|(n, _)| format!("\"{n}\"")).collect();
        return Err(at.error("type", format!("unknown material type \"{}\"; known: {}", m.model, known.join(", "))));
    };
    let given = [
        ("reflectance", m.reflectance),
        ("transmittance", m.transmittance),
        ("specular", m.specular),
        ("exponent", m.exponent),
        ("roughness", m.roughness),
    ];
    for (key, value) in given {
        if value.is_some() && !keys.contains(&key) {
            let message = format!("a \"{}\" material takes only {}", m.model, keys.join(", "));
            return Err(at.error(key, message));
        }
    }
    let fraction = |key: &str, value: Option<f64>| -> Result<f64, SceneError> {
        let v = at.non_negative(key, value.unwrap_or(0.0))?;
        if v > 1.0 {
            return Err(at.error(key, format!("must be at most 1, got {v}")));
        }
        Ok(v)
    };
    let required = |key: &str, value: Option<f64>| {
        value.ok_or_else(|| at.error(key, format!("a \"{}\" material needs `{key}`", m.model)))
    };
    let reflectance = fraction("reflectance", Some(required("reflectance", m.reflectance)?))?;
    let sum_at_most_one = |key: &str, other: f64| {
        if reflectance + other > 1.0 + 1e-12 {
            return Err(at.error(key, format!("reflectance + {key} = {} exceeds 1", reflectance + other)));
        }
        Ok(())
    };
    Ok(match m.model.as_str() {
        "lambert" => {
            let transmittance = fraction("transmittance", m.transmittance)?;
            sum_at_most_one("transmittance", transmittance)?;
            MaterialModel::Lambert { reflectance, transmittance }
        }
        "phong" => {
            let specular = fraction("specular", Some(required("specular", m.specular)?))?;
            sum_at_most_one("specular", specular)?;
            let exponent = at.non_negative("exponent", required("exponent", m.exponent)?)?;
            if exponent > 1e5 {
                return Err(at.error("exponent", format!("must be at most 100000, got {exponent}")));
            }
            MaterialModel::Phong { diffuse: reflectance, specular, exponent }
        }
        "mirror" => MaterialModel::Mirror { reflectance },
        _ => {
            let specular = fraction("specular", Some(required("specular", m.specular)?))?;
            sum_at_most_one("specular", specular)?;
            let roughness = fraction("roughness", Some(required("roughness", m.roughness)?))?;
            if roughness < 1e-3 {
                return Err(at.error("roughness", format!("must be at least 0.001 (use a mirror), got {roughness}")));
            }
            MaterialModel::Ggx { diffuse: reflectance, specular, roughness }
        }
    })
}

fn probes(path: &Path, raw: &[RawProbe]) -> Result<Vec<Probe>, SceneError> {
    unique_names(path, "probe", raw.iter().map(|p| p.name.as_str()))?;
    let probe = |(index, p): (usize, &RawProbe)| {
        let at = Context::item(path, "probe", &p.name, index);
        let position = at.point("position", p.position)?;
        let normal = at.direction("normal", p.normal)?;
        Ok(Probe { name: p.name.clone(), position, normal })
    };
    raw.iter().enumerate().map(probe).collect()
}

fn cameras(path: &Path, raw: &[RawCamera]) -> Result<Vec<Camera>, SceneError> {
    unique_names(path, "camera", raw.iter().map(|c| c.name.as_str()))?;
    raw.iter().enumerate().map(|(index, c)| camera(&Context::item(path, "camera", &c.name, index), c)).collect()
}

/// `Camera::from_keys`: the table rules with `source` in place of a file.
pub fn camera_from_keys(keys: &RawCamera, source: &str) -> Result<Camera, SceneError> {
    camera(&Context::new(Path::new(source), "camera options"), keys)
}

fn camera(at: &Context, c: &RawCamera) -> Result<Camera, SceneError> {
    let position = at.point("position", c.position)?;
    let look_at = at.point("look_at", c.look_at)?;
    let view = (look_at - position)
        .try_normalize()
        .ok_or_else(|| at.error("look_at", format!("must differ from position {}", show(position))))?;
    let up = at.direction("up", c.up.unwrap_or([0.0, 1.0, 0.0]))?;
    if view.cross(up).length() < REL_TOL {
        return Err(at.error("up", format!("must not be parallel to the view direction, got {}", show(up))));
    }
    let fov_deg = at.finite("fov_deg", c.fov_deg.unwrap_or(40.0))?;
    if fov_deg <= 0.0 || fov_deg >= 180.0 {
        return Err(at.error("fov_deg", format!("must be greater than 0 and less than 180, got {fov_deg}")));
    }
    let [w, h] = c.resolution.unwrap_or([512, 512]);
    let pixels = |n: i64| usize::try_from(n).ok().filter(|&n| (1..=16384).contains(&n));
    let (Some(w), Some(h)) = (pixels(w), pixels(h)) else {
        return Err(at.error("resolution", format!("must be two pixel counts from 1 to 16384, got [{w}, {h}]")));
    };
    let samples = match c.samples {
        None => 4,
        Some(n) => usize::try_from(n)
            .ok()
            .filter(|n| (1..=4096).contains(n))
            .ok_or_else(|| at.error("samples", format!("must be from 1 to 4096, got {n}")))?,
    };
    Ok(Camera { name: c.name.clone(), position, look_at, up, fov_deg, resolution: [w, h], samples })
}

fn surfaces(path: &Path, raw: &[RawSurface], materials: &[Material]) -> Result<Vec<Surface>, SceneError> {
    unique_names(path, "surface", raw.iter().map(|s| s.name.as_str()))?;
    raw.iter()
        .enumerate()
        .map(|(index, s)| surface(&Context::item(path, "surface", &s.name, index), s, materials))
        .collect()
}

fn emits(emission: Emission) -> bool {
    match emission {
        Emission::Luminance(x) | Emission::Flux(x) => x > 0.0,
    }
}

fn surface(at: &Context, s: &RawSurface, materials: &[Material]) -> Result<Surface, SceneError> {
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
    Ok(Surface {
        name: s.name.clone(),
        shape: shape(at, s)?,
        material,
        two_sided,
        inside: s.inside.unwrap_or(false),
        emission: s.emission.as_ref().map(|e| emission(at, e)).transpose()?,
    })
}

/// `emission = { luminance = … }` or `{ flux = … }`: exactly one, finite and ≥ 0.
fn emission(at: &Context, raw: &RawEmission) -> Result<Emission, SceneError> {
    match (raw.luminance, raw.flux) {
        (Some(l), None) => Ok(Emission::Luminance(at.non_negative("emission.luminance", l)?)),
        (None, Some(f)) => Ok(Emission::Flux(at.non_negative("emission.flux", f)?)),
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

fn shape(at: &Context, s: &RawSurface) -> Result<Shape, SceneError> {
    let Some(&(name, keys, build)) = SHAPES.iter().find(|(name, ..)| *name == s.shape) else {
        let known: Vec<&str> = SHAPES.iter().map(|(name, ..)| *name).collect();
        let message = format!("unknown shape \"{}\"; known: {}", s.shape, known.join(", "));
        return Err(at.error("shape", message));
    };
    if let Some(stray) = shape_keys_set(s).find(|key| !keys.contains(key)) {
        let message = format!("not a key of shape \"{name}\" (its keys: {})", keys.join(", "));
        return Err(at.error(stray, message));
    }
    build(&ShapeKeys { at, shape: name }, s)
}

/// Reads the keys of one shape, reporting missing required ones.
struct ShapeKeys<'a> {
    at: &'a Context<'a>,
    shape: &'a str,
}

impl ShapeKeys<'_> {
    fn required<T>(&self, key: &str, value: Option<T>) -> Result<T, SceneError> {
        let message = || format!("missing: shape \"{}\" needs `{key}`", self.shape);
        value.ok_or_else(|| self.at.error(key, message()))
    }

    fn point(&self, key: &str, value: Option<[f64; 3]>) -> Result<DVec3, SceneError> {
        self.at.point(key, self.required(key, value)?)
    }

    fn radius(&self, value: Option<f64>) -> Result<f64, SceneError> {
        self.at.positive("radius", self.required("radius", value)?)
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
    if edge_u.cross(edge_v).length() <= REL_TOL * edge_u.length() * edge_v.length() {
        return Err(k.at.error("edge_v", "must not be parallel to `edge_u`"));
    }
    Ok(Shape::Rectangle { origin, edge_u, edge_v })
}

fn polygon(k: &ShapeKeys, s: &RawSurface) -> Result<Shape, SceneError> {
    let raw = k.required("vertices", s.vertices.as_ref())?;
    let vertices = raw.iter().map(|&v| k.at.point("vertices", v)).collect::<Result<Vec<_>, _>>()?;
    polygon_defect(&vertices).map_err(|message| k.at.error("vertices", message))?;
    Ok(Shape::Polygon { vertices })
}

/// Checks that `v` is a usable planar polygon; the error says what is wrong.
fn polygon_defect(v: &[DVec3]) -> Result<(), String> {
    if v.len() < 3 {
        return Err(format!("a polygon needs at least 3 vertices, got {}", v.len()));
    }
    let size = bounding_diagonal(v);
    let next = |i: usize| v[(i + 1) % v.len()];
    if let Some(i) = (0..v.len()).find(|&i| (next(i) - v[i]).length() <= REL_TOL * size) {
        let j = (i + 1) % v.len();
        return Err(format!("vertices #{} and #{} coincide", i + 1, j + 1));
    }
    let far = v.iter().map(|&p| p - v[0]).max_by(|a, b| a.length().total_cmp(&b.length()));
    let axis = far.unwrap_or(DVec3::X).normalize_or_zero();
    if v.iter().all(|&p| (p - v[0]).cross(axis).length() <= REL_TOL * size) {
        return Err("all vertices lie on one line".to_string());
    }
    let newell: DVec3 = (0..v.len()).map(|i| v[i].cross(next(i))).sum();
    if newell.length() / 2.0 <= ZERO_AREA * size * size {
        return Err("the polygon has zero area".to_string());
    }
    let normal = newell.normalize();
    let centre = v.iter().sum::<DVec3>() / v.len() as f64;
    let off = |p: &DVec3| (*p - centre).dot(normal).abs();
    match v.iter().position(|p| off(p) > REL_TOL * size) {
        Some(i) => Err(format!("not planar: vertex #{} is {:.3e} m off the plane", i + 1, off(&v[i]))),
        None => Ok(()),
    }
}

/// The diagonal of the axis-aligned bounding box of `v`.
fn bounding_diagonal(v: &[DVec3]) -> f64 {
    let min = v.iter().fold(DVec3::INFINITY, |m, &p| m.min(p));
    let max = v.iter().fold(DVec3::NEG_INFINITY, |m, &p| m.max(p));
    (max - min).length()
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
    let translate = k.at.point("translate", s.translate.unwrap_or([0.0; 3]))?;
    let file = k.at.file.parent().unwrap_or(Path::new("")).join(name);
    let loaded = load_obj(&file).map_err(|message| k.at.error("file", message))?;
    let placed: Vec<[DVec3; 3]> = loaded.iter().map(|t| t.map(|p| p * scale + translate)).collect();
    if placed.iter().flatten().any(|p| !p.is_finite()) {
        let message = format!("{} has a non-finite vertex (after scaling)", file.display());
        return Err(k.at.error("file", message));
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
fn load_obj(file: &Path) -> Result<Vec<[DVec3; 3]>, String> {
    let shown = file.display();
    std::fs::metadata(file).map_err(|e| format!("cannot open the OBJ file {shown}: {e}"))?;
    let options = tobj::LoadOptions { triangulate: true, single_index: true, ..Default::default() };
    let (models, _materials) =
        tobj::load_obj(file, &options).map_err(|e| format!("cannot read the OBJ file {shown}: {e}"))?;
    let mut triangles = Vec::new();
    for model in &models {
        let mesh = &model.mesh;
        let positions: Vec<DVec3> =
            mesh.positions.chunks_exact(3).map(|p| DVec3::new(p[0].into(), p[1].into(), p[2].into())).collect();
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
