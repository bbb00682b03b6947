//! `[[grid]]` tables: illuminance calculation grids as written, as validated, and their
//! calculation points (the evaluation is `crate::readout::grid`). A grid is its corner,
//! edges and resolution, or the `work_plane` shorthand (`work_plane.rs`).

use super::bounds::surfaces_bounds;
use super::check::{Context, REL_TOL, line, number, show, unique_names};
use super::error::SceneError;
use super::work_plane::{RawWorkPlane, work_plane};
use crate::geometry::Surface;
use glam::DVec3;
use serde::Deserialize;
use serde_spanned::Spanned;
use std::path::Path;

/// `[[grid]]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawGrid {
    pub name: String,
    #[serde(default, deserialize_with = "super::arrays::exact_opt")]
    pub origin: Option<[f64; 3]>,
    #[serde(default, deserialize_with = "super::arrays::exact_opt")]
    pub edge_u: Option<[f64; 3]>,
    #[serde(default, deserialize_with = "super::arrays::exact_opt")]
    pub edge_v: Option<[f64; 3]>,
    #[serde(default, deserialize_with = "super::arrays::exact_opt")]
    pub resolution: Option<[i64; 2]>,
    #[serde(default)]
    pub work_plane: Option<RawWorkPlane>,
    #[serde(default, deserialize_with = "super::arrays::exact_opt")]
    pub normal: Option<[f64; 3]>,
    #[serde(default)]
    pub map: MapStyle,
    #[serde(default)]
    pub target: RawTarget,
}

/// `target = { em = 500, u0 = 0.6, ugr = 19 }` of a `[[grid]]` as written.
#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawTarget {
    pub em: Option<f64>,
    pub u0: Option<f64>,
    pub ugr: Option<Spanned<f64>>,
}

/// The requirements of EN 12464-1 a grid is checked against in the summary and the report:
/// the maintained illuminance `Ēm` (the least `E_avg`), the least uniformity `U0` and the
/// limit `UGR_L` of the largest UGR of the `[[observer]]`s that name the grid. Each may be absent.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Target {
    /// `Ēm`, lx.
    pub em: Option<f64>,
    /// `U0 = E_min / E_avg`.
    pub u0: Option<f64>,
    /// `UGR_L`.
    pub ugr: Option<f64>,
}

/// `map = { scale = "log", values = true, isolines = true }` of a `[[grid]]`: how its plan
/// (`OUT-<grid>.png`) is drawn. Every key is optional.
#[derive(Debug, Clone, Copy, PartialEq, Default, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct MapStyle {
    /// The colour scale: `"linear"` from 0 (default) or `"log"` (four decades).
    pub scale: MapScale,
    /// The value of every cell written on it, lx (where the cells are large enough).
    pub values: bool,
    /// Lines of equal illuminance at the legend's round values.
    pub isolines: bool,
}

/// The colour scale of a grid's plan.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum MapScale {
    /// Linear from 0.
    #[default]
    Linear,
    /// Logarithmic, four decades.
    Log,
}

/// `[[grid]]`: an illuminance calculation grid, the parallelogram
/// `origin + s·edge_u + t·edge_v` divided into `resolution = [nu, nv]` equal cells with a
/// calculation point at the centre of each.
#[derive(Debug, Clone, PartialEq)]
pub struct Grid {
    /// The grid's name, unique in the scene.
    pub name: String,
    /// The corner of the parallelogram, m.
    pub origin: DVec3,
    /// The first edge from `origin`, m.
    pub edge_u: DVec3,
    /// The second edge from `origin`, m.
    pub edge_v: DVec3,
    /// Unit normal of the receiving side, `±(edge_u × edge_v)`.
    pub normal: DVec3,
    /// Calculation points along `edge_u` and `edge_v`, `[nu, nv]`.
    pub resolution: [usize; 2],
    /// How its plan is drawn.
    pub map: MapStyle,
    /// What EN 12464-1 asks of it.
    pub target: Target,
}

impl Grid {
    /// The calculation points, row by row along `edge_u`, rows stepping along `edge_v`.
    pub fn points(&self) -> Vec<DVec3> {
        cell_centres(self.origin, [self.edge_u, self.edge_v], self.resolution)
    }
}

/// The centres of the `resolution = [nu, nv]` equal cells of the parallelogram
/// `origin + s·edges[0] + t·edges[1]`, row by row along `edges[0]`, rows stepping along `edges[1]`.
pub fn cell_centres(origin: DVec3, [edge_u, edge_v]: [DVec3; 2], [nu, nv]: [usize; 2]) -> Vec<DVec3> {
    let at = |a: usize, n: usize| (a as f64 + 0.5) / n as f64;
    (0..nv)
        .flat_map(|b| (0..nu).map(move |a| (a, b)))
        .map(|(a, b)| origin + edge_u * at(a, nu) + edge_v * at(b, nv))
        .collect()
}

pub(super) fn grids(path: &Path, source: &str, raw: &[RawGrid], surfaces: &[Surface]) -> Result<Vec<Grid>, SceneError> {
    unique_names(path, "grid", raw.iter().map(|g| g.name.as_str()))?;
    let bounds = surfaces_bounds(surfaces);
    raw.iter()
        .enumerate()
        .map(|(index, g)| grid(&Context::item(path, "grid", &g.name, index), source, g, bounds))
        .collect()
}

fn grid(at: &Context, source: &str, g: &RawGrid, bounds: (DVec3, DVec3)) -> Result<Grid, SceneError> {
    let target = target(at, source, &g.target)?;
    if let Some(w) = &g.work_plane {
        let given = [("origin", g.origin.is_some()), ("edge_u", g.edge_u.is_some()), ("edge_v", g.edge_v.is_some())];
        let given = given.into_iter().chain([("resolution", g.resolution.is_some()), ("normal", g.normal.is_some())]);
        if let Some((key, _)) = given.into_iter().find(|(_, given)| *given) {
            return Err(at.error(key, "give `work_plane` or the grid's `origin`, edges and `resolution`, not both"));
        }
        let (origin, edge_u, edge_v, resolution) = work_plane(at, w, bounds)?;
        return Ok(Grid {
            name: g.name.clone(),
            origin,
            edge_u,
            edge_v,
            normal: DVec3::Y,
            resolution,
            map: g.map,
            target,
        });
    }
    let needed = |key: &str, value: Option<[f64; 3]>| {
        value.ok_or_else(|| {
            at.error(key, "is missing: give it (with the other corner keys) or `work_plane = { height }`")
        })
    };
    let origin = at.place("origin", needed("origin", g.origin)?)?;
    let [edge_u, edge_v] = edges(at, [needed("edge_u", g.edge_u)?, needed("edge_v", g.edge_v)?])?;
    let front = edge_u.cross(edge_v).normalize();
    let normal = match g.normal {
        None => front,
        Some(n) => {
            let n = at.direction("normal", n)?;
            if n.cross(front).length() > 1e-6 {
                let message = format!("must be perpendicular to the grid, ±{}, got {}", show(front), show(n));
                return Err(at.error("normal", message));
            }
            n
        }
    };
    let Some(resolution) = g.resolution else {
        return Err(at.error("resolution", "is missing: give it as [nu, nv] or use `work_plane = { height }`"));
    };
    let resolution = point_counts(at, resolution, 1000)?;
    Ok(Grid { name: g.name.clone(), origin, edge_u, edge_v, normal, resolution, map: g.map, target })
}

/// `edge_u` and `edge_v` of a parallelogram: lengths, non-zero and not parallel.
pub(super) fn edges(at: &Context, [u, v]: [[f64; 3]; 2]) -> Result<[DVec3; 2], SceneError> {
    let (edge_u, edge_v) = (at.place("edge_u", u)?, at.place("edge_v", v)?);
    let across = edge_u.cross(edge_v);
    if across.length() <= REL_TOL * edge_u.length() * edge_v.length() || across == DVec3::ZERO {
        return Err(at.error("edge_v", "must be non-zero and not parallel to a non-zero `edge_u`"));
    }
    Ok([edge_u, edge_v])
}

/// `resolution = [nu, nv]`: two point counts from 1 to `most`.
pub(super) fn point_counts(at: &Context, [nu, nv]: [i64; 2], most: usize) -> Result<[usize; 2], SceneError> {
    let points = |n: i64| usize::try_from(n).ok().filter(|&n| (1..=most).contains(&n));
    match (points(nu), points(nv)) {
        (Some(nu), Some(nv)) => Ok([nu, nv]),
        _ => Err(at.error("resolution", format!("must be two point counts from 1 to {most}, got [{nu}, {nv}]"))),
    }
}

/// `target`: `em` finite and > 0 lx, `u0` within (0, 1], `ugr` within 0 and 40.
fn target(at: &Context, source: &str, t: &RawTarget) -> Result<Target, SceneError> {
    if let Some(em) = t.em.filter(|e| !(e.is_finite() && *e > 0.0)) {
        return Err(at.error("target", format!("`em` must be a finite illuminance > 0 lx, got {em}")));
    }
    if let Some(u0) = t.u0.filter(|u| !(*u > 0.0 && *u <= 1.0)) {
        return Err(at.error("target", format!("`u0` must lie in (0, 1], got {u0}")));
    }
    if let Some(u) = t.ugr.as_ref().filter(|u| !(0.0..=40.0).contains(u.get_ref())) {
        let message =
            format!("{}`ugr` (UGR_L) must lie within 0 and 40, got {}", line(source, u), number(*u.get_ref()));
        return Err(at.error("target", message));
    }
    Ok(Target { em: t.em, u0: t.u0, ugr: t.ugr.as_ref().map(|u| *u.get_ref()) })
}
