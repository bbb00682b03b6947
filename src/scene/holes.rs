//! `holes = [ … ]` of a rectangle or polygon `[[surface]]`: windows, doors and other openings
//! cut out of it, each a rectangle in the surface's own coordinates (`at` and `size`, m
//! along `edge_u` and `edge_v` from `origin`; rectangles only) or a polygon (`vertices` in
//! the surface's plane). Owns the rules a hole obeys: a simple polygon in the surface's
//! plane, within the surface (touching its edge is allowed: a door at the floor), sharing
//! no area with another hole, and leaving some of the surface; the rectangle of `at` and
//! `size` is also how a `[[window]]` is placed in its wall (`window_place.rs`).

use super::check::{Context, REL_TOL, line, number};
use super::error::SceneError;
use super::polygon::polygon_defect;
use crate::geometry::{Shape, hole_faults, tessellate};
use glam::DVec3;
use serde::Deserialize;
use serde_spanned::Spanned;

/// One hole as written: `{ at = [u, v], size = [w, h] }` or `{ vertices = [[x, y, z], …] }`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawHole {
    #[serde(default, deserialize_with = "super::arrays::exact_opt")]
    pub at: Option<[f64; 2]>,
    #[serde(default, deserialize_with = "super::arrays::exact_opt")]
    pub size: Option<[f64; 2]>,
    #[serde(default, deserialize_with = "super::arrays::exact_list")]
    pub vertices: Option<Vec<[f64; 3]>>,
}

/// A rectangle surface's frame, in which `at` and `size` are measured.
#[derive(Debug, Clone, Copy)]
pub(super) struct Frame {
    pub origin: DVec3,
    pub edge_u: DVec3,
    pub edge_v: DVec3,
}

impl Frame {
    /// Its corners, counter-clockwise seen from its front (`edge_u × edge_v`).
    pub(super) fn outline(&self) -> Vec<DVec3> {
        let Frame { origin: o, edge_u: u, edge_v: v } = *self;
        vec![o, o + u, o + u + v, o + v]
    }

    /// The rectangle from `at` to `at + size` (m along `edge_u` and `edge_v`) as
    /// `[corner, edge along u, edge along v]`, or the key (`at` or `size`) at fault and why.
    pub(super) fn rectangle(&self, at: [f64; 2], size: [f64; 2]) -> Result<[DVec3; 3], (&'static str, String)> {
        let both = |v: [f64; 2]| format!("[{}, {}]", number(v[0]), number(v[1]));
        if !at.iter().chain(&size).all(|x| x.is_finite()) {
            return Err(("at", format!("must be finite, got at = {}, size = {}", both(at), both(size))));
        }
        if size.iter().any(|&s| s <= 0.0) {
            return Err(("size", format!("must be greater than 0 along both edges, got {}", both(size))));
        }
        let lengths = [self.edge_u.length(), self.edge_v.length()];
        for (i, edge) in ["edge_u", "edge_v"].into_iter().enumerate() {
            let slack = REL_TOL * lengths[i];
            if at[i] < -slack {
                return Err(("at", format!("must be at least 0 m along {edge}, got {}", number(at[i]))));
            }
            if size[i] > lengths[i] + slack {
                let message = format!(
                    "is larger than the surface: {} m along {edge}, which is {} m long",
                    number(size[i]),
                    number(lengths[i])
                );
                return Err(("size", message));
            }
            if at[i] + size[i] > lengths[i] + slack {
                let message = format!(
                    "reaches beyond the surface: at + size = {} m along {edge}, which is {} m long",
                    number(at[i] + size[i]),
                    number(lengths[i])
                );
                return Err(("at", message));
            }
        }
        let (u, v) = (self.edge_u / lengths[0], self.edge_v / lengths[1]);
        Ok([self.origin + at[0] * u + at[1] * v, size[0] * u, size[1] * v])
    }
}

/// The corners of `[corner, edge u, edge v]`.
pub(super) fn corners([o, u, v]: [DVec3; 3]) -> Vec<DVec3> {
    vec![o, o + u, o + u + v, o + v]
}

/// The surface `outline` less the holes of `raw` (of the table at `at`; `frame` for a
/// rectangle, which may give holes by `at` and `size`).
pub(super) fn holed(
    at: &Context,
    source: &str,
    outline: Vec<DVec3>,
    frame: Option<Frame>,
    raw: &Spanned<Vec<RawHole>>,
) -> Result<Shape, SceneError> {
    let fail = |key: String, message: String| at.error(&key, format!("{}{message}", line(source, raw)));
    let size = outline.iter().map(|p| p.distance(outline[0])).fold(0.0, f64::max);
    let n = outline.len();
    let normal = (0..n).map(|i| outline[i].cross(outline[(i + 1) % n])).sum::<DVec3>().normalize();
    let mut holes = Vec::new();
    for (j, hole) in raw.get_ref().iter().enumerate() {
        let key = |what: &str| format!("holes[{}].{what}", j + 1);
        let vertices = match (&hole.vertices, hole.at, hole.size, frame) {
            (Some(_), Some(_), _, _) | (Some(_), _, Some(_), _) => {
                return Err(fail(key("vertices"), "give `vertices`, or `at` and `size`, not both".into()));
            }
            (Some(v), None, None, _) => {
                polygon_hole(v, &outline, normal, size).map_err(|m| fail(key("vertices"), m))?
            }
            (None, Some(a), Some(s), Some(frame)) => corners(frame.rectangle(a, s).map_err(|(k, m)| fail(key(k), m))?),
            (None, _, _, None) => {
                let message = "a polygon's holes are polygons: give `vertices` (`at` and `size` are for rectangles)";
                return Err(fail(key("vertices"), message.into()));
            }
            (None, _, _, Some(_)) => {
                let message = "give `at` and `size` (m along edge_u and edge_v from origin), or `vertices`";
                return Err(fail(key(if hole.at.is_none() { "at" } else { "size" }), message.into()));
            }
        };
        holes.push(vertices);
    }
    if holes.is_empty() {
        return Err(fail("holes".into(), "is empty: give at least one hole, or no `holes`".into()));
    }
    let shape = Shape::Holed { outline, holes };
    fault(&shape, &|j| format!("hole #{}", j + 1)).map_err(|(j, m)| fail(format!("holes[{}]", j + 1), m))?;
    Ok(shape)
}

/// A hole given by its vertices: a simple polygon in the outline's plane.
fn polygon_hole(raw: &[[f64; 3]], outline: &[DVec3], normal: DVec3, size: f64) -> Result<Vec<DVec3>, String> {
    let vertices: Vec<DVec3> = raw.iter().map(|&v| DVec3::from_array(v)).collect();
    if let Some(i) = vertices.iter().position(|p| !p.is_finite()) {
        return Err(format!("vertex #{} is not finite", i + 1));
    }
    polygon_defect(&vertices)?;
    let off = |p: &DVec3| (*p - outline[0]).dot(normal).abs();
    match vertices.iter().position(|p| off(p) > REL_TOL * size) {
        Some(i) => Err(format!("vertex #{} is {:.3e} m off the surface's plane", i + 1, off(&vertices[i]))),
        None => Ok(vertices),
    }
}

/// The first fault of the holes of `shape` (a [`Shape::Holed`]): a hole partly outside the
/// surface, two holes sharing area, or nothing left; `name(j)` names hole `j` in the
/// message. Returns the index of the (last) hole at fault and the message.
pub(super) fn fault(shape: &Shape, name: &dyn Fn(usize) -> String) -> Result<(), (usize, String)> {
    let Shape::Holed { outline, holes } = shape else { return Ok(()) };
    let size = outline.iter().map(|p| p.distance(outline[0])).fold(0.0, f64::max);
    let tolerance = 1e-9 * size * size;
    let faults = hole_faults(outline, holes);
    if let Some(j) = (0..holes.len()).find(|&j| faults.outside[j] > tolerance) {
        let message = format!("{} reaches outside the surface ({:.4e} m² of it)", name(j), faults.outside[j]);
        return Err((j, message));
    }
    if let Some(&(j, k, area)) = faults.overlaps.iter().find(|(_, _, area)| *area > tolerance) {
        return Err((k, format!("{} overlaps {} ({area:.4e} m² in common)", name(k), name(j))));
    }
    let left: f64 = tessellate(shape, f64::INFINITY).iter().map(|e| e.area()).sum();
    if left <= tolerance {
        return Err((
            holes.len() - 1,
            format!("the holes leave nothing of the surface (up to {})", name(holes.len() - 1)),
        ));
    }
    Ok(())
}
