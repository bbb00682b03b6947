//! Where a `[[window]]` is: by its corner and edges (`origin`, `edge_u`, `edge_v`), or by
//! its place in a wall (`wall`, the name of a rectangle `[[surface]]`; `at` and `size`, m
//! along the wall's `edge_u` and `edge_v` from its `origin`, as a hole of the wall is given).
//! Owns both forms' rules and the cut: a window placed in a wall becomes a hole of it (the
//! wall turns into a `Shape::Holed`), so the user does not model the wall as rectangles
//! around the opening. The window must lie within its wall and share no area with the
//! wall's own holes or the other windows cut into it.

use super::check::{Context, REL_TOL, line, show};
use super::error::SceneError;
use super::holes::{Frame, corners, fault};
use super::schema::RawSurface;
use super::sky::RawWindow;
use crate::geometry::{Shape, Surface};
use glam::DVec3;
use std::path::Path;

/// The corner and edges `[origin, edge_u, edge_v]` of every window, in table order; each
/// window placed in a wall cut into that wall among `surfaces` (built from `raw_surfaces`,
/// `tables` the table of each surface).
pub(super) fn placements(
    path: &Path,
    source: &str,
    windows: &[RawWindow],
    raw_surfaces: &[RawSurface],
    surfaces: &mut [Surface],
    tables: &[usize],
) -> Result<Vec<[DVec3; 3]>, SceneError> {
    let mut cut: Vec<(usize, String)> = Vec::new();
    let mut placed = Vec::with_capacity(windows.len());
    for (index, w) in windows.iter().enumerate() {
        let at = Context::item(path, "window", &w.name, index);
        let Some(wall) = &w.wall else {
            placed.push(corner_and_edges(&at, w)?);
            continue;
        };
        let fail = |key: &str, message: String| at.error(key, format!("{}{message}", line(source, wall)));
        let name = wall.get_ref();
        let given = [("origin", w.origin.is_some()), ("edge_u", w.edge_u.is_some()), ("edge_v", w.edge_v.is_some())];
        if let Some((key, _)) = given.iter().find(|(_, set)| *set) {
            return Err(fail(key, format!("a window in a `wall` is placed by `at` and `size`: give no `{key}`")));
        }
        let (Some(corner), Some(size)) = (w.at, w.size) else {
            let key = if w.at.is_none() { "at" } else { "size" };
            let message = "a window in a `wall` needs `at` (its corner, m along the wall's edge_u and edge_v from \
                           its origin) and `size` (m along them)";
            return Err(fail(key, message.to_string()));
        };
        let table = wall_table(raw_surfaces, name).map_err(|message| fail("wall", message))?;
        let s = &raw_surfaces[table];
        let vector = |v: Option<[f64; 3]>| DVec3::from_array(v.unwrap_or_default());
        let frame = Frame { origin: vector(s.origin), edge_u: vector(s.edge_u), edge_v: vector(s.edge_v) };
        let rectangle =
            frame.rectangle(corner, size).map_err(|(key, m)| fail(key, format!("in the wall \"{name}\": {m}")))?;
        let surface = tables.iter().position(|&t| t == table).unwrap_or_default();
        let windows_in: Vec<&str> = cut.iter().filter(|(s, _)| *s == surface).map(|(_, n)| n.as_str()).collect();
        let shape = cut_into(&surfaces[surface].shape, frame, rectangle, &windows_in, &w.name)
            .map_err(|message| fail("at", message))?;
        surfaces[surface].shape = shape;
        cut.push((surface, w.name.clone()));
        placed.push(rectangle);
    }
    Ok(placed)
}

/// The wall of `shape` (of `frame`) with the window `rectangle` named `name` cut out besides
/// its holes and the windows `windows_in` already cut into it, or why it cannot be.
fn cut_into(
    shape: &Shape,
    frame: Frame,
    rectangle: [DVec3; 3],
    windows_in: &[&str],
    name: &str,
) -> Result<Shape, String> {
    let (outline, mut holes) = match shape {
        Shape::Holed { outline, holes } => (outline.clone(), holes.clone()),
        _ => (frame.outline(), Vec::new()),
    };
    holes.push(corners(rectangle));
    let own = holes.len() - 1 - windows_in.len();
    let naming = |j: usize| match j.checked_sub(own) {
        None => format!("the wall's hole #{}", j + 1),
        Some(k) => format!("[[window]] \"{}\"", windows_in.get(k).copied().unwrap_or(name)),
    };
    let shape = Shape::Holed { outline, holes };
    fault(&shape, &naming).map_err(|(_, message)| message)?;
    Ok(shape)
}

/// The table of the rectangle `[[surface]]` named `name`, which takes no copies.
fn wall_table(raw: &[RawSurface], name: &str) -> Result<usize, String> {
    let Some(table) = raw.iter().position(|s| s.name == name) else {
        let known: Vec<String> =
            raw.iter().filter(|s| s.shape == "rectangle").map(|s| format!("\"{}\"", s.name)).collect();
        return Err(format!("no [[surface]] is named \"{name}\"; the rectangles: {}", known.join(", ")));
    };
    let s = &raw[table];
    if s.shape != "rectangle" {
        return Err(format!("the wall \"{name}\" is a {}: a window is cut into a rectangle", s.shape));
    }
    if s.array.is_some() || s.transforms.is_some() {
        return Err(format!("the wall \"{name}\" is copied (`array` or `transforms`): a window is cut into one wall"));
    }
    Ok(table)
}

/// A window by its corner and edges, which must span an area.
fn corner_and_edges(at: &Context, w: &RawWindow) -> Result<[DVec3; 3], SceneError> {
    if let Some(key) = [("at", w.at.is_some()), ("size", w.size.is_some())].iter().find(|(_, set)| *set).map(|k| k.0) {
        return Err(at.error(key, "places a window in its `wall`: give `wall` too, or `origin`, `edge_u` and `edge_v`"));
    }
    let required = |key: &str, v: Option<[f64; 3]>| {
        let message = "missing: give `origin`, `edge_u` and `edge_v`, or the window's `wall`, `at` and `size`";
        at.place(key, v.ok_or_else(|| at.error(key, message))?)
    };
    let origin = required("origin", w.origin)?;
    let u = required("edge_u", w.edge_u)?;
    let v = required("edge_v", w.edge_v)?;
    if u.cross(v).length() <= REL_TOL * u.length() * v.length() || u.length() == 0.0 || v.length() == 0.0 {
        return Err(at.error("edge_v", format!("edge_u {} and edge_v {} span no area", show(u), show(v))));
    }
    Ok([origin, u, v])
}
