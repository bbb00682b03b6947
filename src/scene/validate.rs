//! Checks the raw tables of a case file and builds the runtime [`Scene`].
//!
//! Owns every rule of `docs/design.md` §7 that serde cannot express for the scene as a whole
//! (among them, across tables: a `[[grid]]`'s `ugr` target needs an observer or a glare
//! grid naming it) and its small tables (`[scene]`, `[discretization]`, `[solver]`,
//! cameras); the large tables have their own files (`material.rs`, `surface.rs`, `grid.rs`,
//! `luminaire.rs`, `probe.rs`, `observer.rs`, `glare_grid.rs`). Each failure is a [`SceneError`] naming the table
//! (`[[surface]] "floor" (#3)`) and the key.

use super::automatic::by_size;
use super::check::{Context, REL_TOL, line, number, show, unique_names};
use super::description::{Camera, Scene, SolverSettings};
use super::discretization_keys;
use super::error::SceneError;
use super::files::CaseFiles;
use super::glare_grid::{GlareGrid, glare_grids};
use super::grid::{Grid, RawGrid, grids};
use super::light_scene::{Sources, lighting};
use super::luminaire::luminaires;
use super::material::materials;
use super::observer::{Observer, observers};
use super::probe::probes;
use super::schema::{RawCamera, RawScene, RawSceneInfo, RawSolver};
use super::sky::{daylight, glaze};
use super::surface::{emits, surfaces};
use super::window_place::placements;
use crate::solve::Method;
use std::cell::RefCell;
use std::path::Path;

/// Validates the raw tables of the case file `path` (whose text is `source`).
pub fn validate(path: &Path, source: String, raw: RawScene, files: CaseFiles) -> Result<Scene, SceneError> {
    let (name, description) = scene_info(path, raw.scene);
    let (asked, old_spelling) = discretization_keys::asked(path, raw.discretization)?;
    let solver = solver(path, raw.solver)?;
    if raw.surface.is_empty() {
        return Err(SceneError::new(path, "[[surface]]", "", "the scene has no [[surface]]"));
    }
    let (materials, file_warnings) = (RefCell::new(materials(path, &raw.material)?), RefCell::default());
    let (mut surfaces, surface_tables) = surfaces(path, &source, &raw.surface, (&materials, &file_warnings), &files)?;
    let placed = placements(path, &source, &raw.window, &raw.surface, &mut surfaces, &surface_tables)?;
    let probes = probes(path, &raw.probe)?;
    let cameras = cameras(path, &raw.camera)?;
    let grids = grids(path, &source, &raw.grid, &surfaces)?;
    let observers = observers(path, &source, &raw.observer, &grids)?;
    let glare_grids = glare_grids(path, &source, &raw.glare_grid, &grids)?;
    ugr_targets_read(path, &source, (&grids, &raw.grid), (&observers, &glare_grids))?;
    let (mut luminaires, groups) = luminaires(path, &source, &raw.luminaire, &files)?;
    let (sky, openings, glass) = daylight(path, raw.sky.as_ref(), &raw.window, &placed)?;
    glaze(&mut luminaires, &glass);
    if let Some(clash) = openings.iter().find(|o| luminaires.iter().any(|l| l.name == o.name)) {
        let message = format!("\"{}\" names a [[luminaire]] and a [[window]] or the [sky]'s sun", clash.name);
        return Err(SceneError::new(path, "[[luminaire]]", "name", message));
    }
    luminaires.extend(openings);
    if luminaires.is_empty() && !surfaces.iter().any(|s| s.emission.is_some_and(emits)) {
        let message = "nothing emits light: give a [[surface]] an `emission` greater than 0, or add a [[luminaire]]";
        return Err(SceneError::new(path, "", "emission", message));
    }
    let sources = Sources {
        surface_groups: surface_tables.iter().map(|&t| raw.surface[t].group.clone()).collect(),
        // windows and the sun (after the tables' luminaires) belong to the default group
        luminaire_groups: groups
            .iter()
            .cloned()
            .chain(std::iter::repeat_with(|| None))
            .take(luminaires.len())
            .collect(),
        surfaces: &mut surfaces,
        luminaires: &mut luminaires,
        electric: groups.len(),
    };
    let lighting = lighting(path, &source, raw.lighting, &raw.light_scene, sources)?;
    let discretization = asked.resolve(path, |h, directions| by_size(h, directions, &surfaces, &materials.borrow()))?;
    Ok(Scene {
        path: path.to_path_buf(),
        source,
        name,
        description,
        asked,
        discretization,
        old_spelling,
        solver,
        materials: materials.into_inner(),
        file_warnings: file_warnings.into_inner(),
        surfaces,
        probes,
        observers,
        glare_grids,
        cameras,
        grids,
        luminaires,
        sky,
        lighting,
        files: files.into_read(),
    })
}

/// Where a value sits: the case file and the table being validated.
/// `[scene]`: the name (default: the file stem) and the description (default empty).
fn scene_info(path: &Path, info: Option<RawSceneInfo>) -> (String, String) {
    let info = info.unwrap_or(RawSceneInfo { name: None, description: None });
    let stem = || path.file_stem().map(|s| s.to_string_lossy().into_owned());
    let name = info.name.or_else(stem).unwrap_or_default();
    (name, info.description.unwrap_or_default())
}

fn solver(path: &Path, raw: Option<RawSolver>) -> Result<SolverSettings, SceneError> {
    let at = Context::new(path, "[solver]");
    let default = SolverSettings::default();
    let Some(raw) = raw else { return Ok(default) };
    let tolerance = at.finite("tolerance", raw.tolerance.unwrap_or(default.tolerance))?;
    if tolerance <= 0.0 || tolerance >= 1.0 {
        let message = format!("must be greater than 0 and less than 1, got {}", number(tolerance));
        return Err(at.error("tolerance", message));
    }
    let max_iterations = match raw.max_iterations {
        None => default.max_iterations,
        Some(n) => usize::try_from(n)
            .ok()
            .filter(|&n| n >= 1)
            .ok_or_else(|| at.error("max_iterations", format!("must be at least 1, got {n}")))?,
    };
    let method = match raw.method {
        None => default.method,
        Some(name) => Method::parse(&name)
            .ok_or_else(|| at.error("method", format!("unknown method \"{name}\"; known: {}", Method::names())))?,
    };
    Ok(SolverSettings { method, tolerance, max_iterations })
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
        return Err(at.error("fov_deg", format!("must be greater than 0 and less than 180, got {}", number(fov_deg))));
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

/// Refuses a grid with a `ugr` target (`raw_grids` for its line) that no observer and no
/// glare grid names: a grid's UGR is the largest of the observers and glare grids that
/// name it.
fn ugr_targets_read(
    path: &Path,
    source: &str,
    (grids, raw_grids): (&[Grid], &[RawGrid]),
    (observers, glare_grids): (&[Observer], &[GlareGrid]),
) -> Result<(), SceneError> {
    let named: Vec<&str> = observers
        .iter()
        .filter_map(|o| o.grid.as_deref())
        .chain(glare_grids.iter().filter_map(|g| g.grid.as_deref()))
        .collect();
    let unread = grids.iter().zip(raw_grids).enumerate().find_map(|(index, (grid, raw))| {
        let limit = raw.target.ugr.as_ref().filter(|_| !named.contains(&grid.name.as_str()))?;
        Some((index, grid, limit))
    });
    let Some((index, grid, limit)) = unread else {
        return Ok(());
    };
    let message = format!(
        "{}`ugr` (UGR_L) needs an [[observer]] or a [[glare_grid]] with `grid = \"{}\"`: a grid's UGR is the \
         largest of the observers and glare grids that name it",
        line(source, limit),
        grid.name
    );
    Err(Context::item(path, "grid", &grid.name, index).error("target", message))
}
