//! `array = { … }` of a `[[luminaire]]`: one table placing a rectangular array of
//! luminaires, each aimed, rotated and dimmed alike (issue 17, item 2).
//!
//! Two forms, never both:
//!
//! * spacings: `rows`, `columns`, `row_spacing`, `column_spacing` (m) from the table's
//!   `position` (the luminaire of row 1, column 1); columns step along `axis_u` (default
//!   `[1, 0, 0]`), rows along `axis_v` (default `[0, 0, 1]`);
//! * a rectangle: `rows × columns` spread over `origin + s·edge_u + t·edge_v` (columns along
//!   `edge_u`, rows along `edge_v`) with `offset = [a_u, a_v]`, the distance (m) of the
//!   outer luminaires from the edges; without `offset` each luminaire sits at the centre of
//!   its cell (`a = edge/(2n)`, spacing `edge/n`), with it the spacing is `(edge − 2a)/(n − 1)`.
//!
//! The luminaire of row `r`, column `c` (from 1) is named `NAME-r-c`. The members dim
//! together, in the table's `group`, unless `group_by` splits them: `"row"` puts row `r` in
//! the group `GROUP-row-r`, `"column"` column `c` in `GROUP-column-c`, `"member"` each in
//! `GROUP-r-c` (`GROUP` the table's `group`, or its `name` without one). This module
//! computes the positions and the groups; `luminaire.rs` copies the rest of the table to
//! each.

use super::check::{Context, REL_TOL, line, show};
use super::error::SceneError;
use glam::DVec3;
use serde::Deserialize;
use serde_spanned::Spanned;

/// The most luminaires one array may place.
const MOST: i64 = 10_000;

/// `array = { … }` as written.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawArray {
    pub rows: i64,
    pub columns: i64,
    pub row_spacing: Option<f64>,
    pub column_spacing: Option<f64>,
    #[serde(default, deserialize_with = "super::arrays::exact_opt")]
    pub axis_u: Option<[f64; 3]>,
    #[serde(default, deserialize_with = "super::arrays::exact_opt")]
    pub axis_v: Option<[f64; 3]>,
    #[serde(default, deserialize_with = "super::arrays::exact_opt")]
    pub origin: Option<[f64; 3]>,
    #[serde(default, deserialize_with = "super::arrays::exact_opt")]
    pub edge_u: Option<[f64; 3]>,
    #[serde(default, deserialize_with = "super::arrays::exact_opt")]
    pub edge_v: Option<[f64; 3]>,
    #[serde(default, deserialize_with = "super::arrays::exact_opt")]
    pub offset: Option<[f64; 2]>,
    /// Splits the array's group by `"row"`, `"column"` or `"member"`.
    pub group_by: Option<String>,
}

/// How an array's members are grouped for dimming.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum GroupBy {
    /// All in the table's group.
    Whole,
    Row,
    Column,
    Member,
}

impl GroupBy {
    /// The group of the member at `row`, `column` (from 1) of an array whose group is `stem`,
    /// or `None` when it keeps the table's.
    pub(super) fn group_of(self, stem: &str, row: usize, column: usize) -> Option<String> {
        match self {
            GroupBy::Whole => None,
            GroupBy::Row => Some(format!("{stem}-row-{row}")),
            GroupBy::Column => Some(format!("{stem}-column-{column}")),
            GroupBy::Member => Some(format!("{stem}-{row}-{column}")),
        }
    }
}

/// One placed member of an array: its row and column (from 1), name suffix (`-r-c`) and
/// position.
pub(super) struct Member {
    pub row: usize,
    pub column: usize,
    pub suffix: String,
    pub position: DVec3,
}

/// The `group_by` of `array` (read from the case text `source`, for its line).
pub(super) fn group_by(at: &Context, source: &str, array: &Spanned<RawArray>) -> Result<GroupBy, SceneError> {
    match array.get_ref().group_by.as_deref() {
        None => Ok(GroupBy::Whole),
        Some("row") => Ok(GroupBy::Row),
        Some("column") => Ok(GroupBy::Column),
        Some("member") => Ok(GroupBy::Member),
        Some(other) => Err(at.error(
            "array.group_by",
            format!("{}must be \"row\", \"column\" or \"member\", got \"{other}\"", line(source, array)),
        )),
    }
}

/// The members of `array` (read from the case text `source`, for its line), the first at
/// `position` in the spacing form; `position` must be absent in the rectangle form.
pub(super) fn members(
    at: &Context,
    source: &str,
    array: &Spanned<RawArray>,
    position: Option<DVec3>,
) -> Result<Vec<Member>, SceneError> {
    let raw = array.get_ref();
    let fail =
        |key: &str, message: String| at.error(&format!("array.{key}"), format!("{}{message}", line(source, array)));
    let count = |key: &str, n: i64| match (1..=MOST).contains(&n) {
        true => Ok(n as usize),
        false => Err(fail(key, format!("must be a count from 1 to {MOST}, got {n}"))),
    };
    let (rows, columns) = (count("rows", raw.rows)?, count("columns", raw.columns)?);
    if rows * columns > MOST as usize {
        return Err(fail("rows", format!("{rows} × {columns} luminaires: at most {MOST} in one array")));
    }
    let first_given = |keys: [(&'static str, bool); 4]| keys.into_iter().find(|(_, set)| *set).map(|(key, _)| key);
    let spacing = first_given([
        ("row_spacing", raw.row_spacing.is_some()),
        ("column_spacing", raw.column_spacing.is_some()),
        ("axis_u", raw.axis_u.is_some()),
        ("axis_v", raw.axis_v.is_some()),
    ]);
    let rectangle = first_given([
        ("origin", raw.origin.is_some()),
        ("edge_u", raw.edge_u.is_some()),
        ("edge_v", raw.edge_v.is_some()),
        ("offset", raw.offset.is_some()),
    ]);
    let steps = match (spacing, rectangle) {
        (Some(a), Some(b)) => {
            let message = format!(
                "give either spacings (`row_spacing`, `column_spacing`, `axis_u`, `axis_v`, from `position`) or a \
                 rectangle (`origin`, `edge_u`, `edge_v`, `offset`), not both: `{a}` and `{b}` are given"
            );
            return Err(fail(b, message));
        }
        (_, Some(_)) => {
            if position.is_some() {
                let message = "an array spread over a rectangle places its luminaires itself: give no `position`";
                return Err(at.error("position", format!("{}{message}", line(source, array))));
            }
            rectangle_steps(&fail, raw, [columns, rows])?
        }
        (_, None) => {
            let Some(first) = position else {
                let message = "an array by spacings starts at `position` (row 1, column 1): give it";
                return Err(at.error("position", format!("{}{message}", line(source, array))));
            };
            spacing_steps(&fail, raw, first, [columns, rows])?
        }
    };
    let [start, step_u, step_v] = steps;
    let member = |r: usize, c: usize| Member {
        row: r + 1,
        column: c + 1,
        suffix: format!("-{}-{}", r + 1, c + 1),
        position: start + step_u * c as f64 + step_v * r as f64,
    };
    Ok((0..rows).flat_map(|r| (0..columns).map(move |c| (r, c))).map(|(r, c)| member(r, c)).collect())
}

/// What fails with a key of the array and a message.
type Fail<'a> = dyn Fn(&str, String) -> SceneError + 'a;

/// `[first, column step, row step]` of the spacing form.
fn spacing_steps(
    fail: &Fail,
    raw: &RawArray,
    first: DVec3,
    [columns, rows]: [usize; 2],
) -> Result<[DVec3; 3], SceneError> {
    let axis = |key: &str, v: Option<[f64; 3]>, default: DVec3| match v {
        None => Ok(default),
        Some(v) => {
            let d = DVec3::from_array(v);
            let unit = d.is_finite().then(|| d.try_normalize()).flatten();
            unit.ok_or_else(|| fail(key, format!("must be a non-zero finite vector, got {}", show(d))))
        }
    };
    let u = axis("axis_u", raw.axis_u, DVec3::X)?;
    let v = axis("axis_v", raw.axis_v, DVec3::Z)?;
    if u.cross(v).length() <= REL_TOL {
        return Err(fail("axis_v", format!("must not be parallel to `axis_u` {}", show(u))));
    }
    let spacing = |key: &str, value: Option<f64>, n: usize| match (value, n) {
        (None, 1) => Ok(0.0),
        (None, _) => Err(fail(key, format!("{n} of them need `{key}` (m, greater than 0)"))),
        (Some(s), _) if s.is_finite() && s > 0.0 && s <= super::check::COORDINATE => Ok(s),
        (Some(s), _) => Err(fail(key, format!("must be a distance greater than 0 m, got {s}"))),
    };
    let column_spacing = spacing("column_spacing", raw.column_spacing, columns)?;
    let row_spacing = spacing("row_spacing", raw.row_spacing, rows)?;
    Ok([first, u * column_spacing, v * row_spacing])
}

/// `[first, column step, row step]` of the rectangle form.
fn rectangle_steps(fail: &Fail, raw: &RawArray, [columns, rows]: [usize; 2]) -> Result<[DVec3; 3], SceneError> {
    let vector = |key: &str, v: Option<[f64; 3]>| {
        let v = v.ok_or_else(|| {
            fail(key, "an array spread over a rectangle needs `origin`, `edge_u` and `edge_v`".into())
        })?;
        let p = DVec3::from_array(v);
        match p.is_finite() && p.abs().max_element() <= super::check::COORDINATE {
            true => Ok(p),
            false => Err(fail(key, format!("must have finite coordinates within ±1e6 m, got {}", show(p)))),
        }
    };
    let origin = vector("origin", raw.origin)?;
    let (edge_u, edge_v) = (vector("edge_u", raw.edge_u)?, vector("edge_v", raw.edge_v)?);
    let across = edge_u.cross(edge_v);
    if across == DVec3::ZERO || across.length() <= REL_TOL * edge_u.length() * edge_v.length() {
        return Err(fail("edge_v", "must be non-zero and not parallel to a non-zero `edge_u`".into()));
    }
    let Some([a_u, a_v]) = raw.offset else {
        let (du, dv) = (edge_u / columns as f64, edge_v / rows as f64);
        return Ok([origin + (du + dv) / 2.0, du, dv]);
    };
    let spread = |edge: DVec3, a: f64, n: usize| -> Result<(DVec3, DVec3), SceneError> {
        let length = edge.length();
        let fits = if n == 1 { 2.0 * a <= length } else { 2.0 * a < length };
        if !(a.is_finite() && a >= 0.0 && fits) {
            let what = format!("an edge offset is from 0 m to less than half its edge ({length} m), got {a}");
            return Err(fail("offset", what));
        }
        let unit = edge / length;
        Ok(match n {
            1 => (edge / 2.0, DVec3::ZERO),
            _ => (unit * a, unit * ((length - 2.0 * a) / (n - 1) as f64)),
        })
    };
    let (start_u, du) = spread(edge_u, a_u, columns)?;
    let (start_v, dv) = spread(edge_v, a_v, rows)?;
    Ok([origin + start_u + start_v, du, dv])
}
