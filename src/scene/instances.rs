//! Copies of a `[[surface]]` (furniture instancing, issue 38 point 4): `array = { count,
//! step }` places copies on a lattice of up to three steps, `transforms = [ … ]` one copy
//! per listed motion (a turn about an axis through a pivot, then a move). Owns both keys'
//! rules and the copies' names: the copy of lattice index `(i, j)` (from 1) is `NAME-i-j`,
//! the `k`-th transform's `NAME-k`. The surface is built once (an OBJ file read once) and
//! each copy is its shape moved (`geometry::Motion`).

use super::check::{COORDINATE, Context, line, number, show};
use super::error::SceneError;
use crate::geometry::Motion;
use glam::DVec3;
use serde::Deserialize;
use serde_spanned::Spanned;

/// The most copies one table may make.
const MOST: usize = 10_000;

/// `array = { count = [n1, n2], step = [[x, y, z], [x, y, z]] }` as written.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawArray {
    pub count: Vec<i64>,
    #[serde(default, deserialize_with = "super::arrays::exact_list")]
    pub step: Option<Vec<[f64; 3]>>,
}

/// One entry of `transforms = [ … ]` as written.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawTransform {
    #[serde(default, deserialize_with = "super::arrays::exact_opt")]
    pub translate: Option<[f64; 3]>,
    pub rotate_deg: Option<f64>,
    #[serde(default, deserialize_with = "super::arrays::exact_opt")]
    pub rotate_axis: Option<[f64; 3]>,
    #[serde(default, deserialize_with = "super::arrays::exact_opt")]
    pub pivot: Option<[f64; 3]>,
}

/// One copy: the suffix of its name and its motion.
pub(super) struct Copy {
    pub suffix: String,
    pub motion: Motion,
    /// The key that asked for it, for an error about it.
    pub key: String,
}

/// The copies a table asks for by its `array` or `transforms`, `centre` the default pivot
/// (the centre of its bounding box); none when it asks for none (it stands as written).
pub(super) fn copies(
    at: &Context,
    source: &str,
    array: Option<&Spanned<RawArray>>,
    transforms: Option<&Spanned<Vec<RawTransform>>>,
    centre: DVec3,
) -> Result<Vec<Copy>, SceneError> {
    match (array, transforms) {
        (Some(_), Some(transforms)) => {
            let message = format!("{}give `array` or `transforms`, not both", line(source, transforms));
            Err(at.error("transforms", message))
        }
        (Some(array), None) => lattice(at, source, array),
        (None, Some(transforms)) => listed(at, source, transforms, centre),
        (None, None) => Ok(Vec::new()),
    }
}

/// The copies of `array`: every index of the lattice, offset by `Σ (index − 1)·step`.
fn lattice(at: &Context, source: &str, array: &Spanned<RawArray>) -> Result<Vec<Copy>, SceneError> {
    let fail =
        |key: &str, message: String| at.error(&format!("array.{key}"), format!("{}{message}", line(source, array)));
    let raw = array.get_ref();
    if !(1..=3).contains(&raw.count.len()) {
        return Err(fail("count", format!("must list 1 to 3 counts, got {}", raw.count.len())));
    }
    let mut counts = Vec::new();
    for &n in &raw.count {
        match usize::try_from(n).ok().filter(|n| (1..=MOST).contains(n)) {
            Some(n) => counts.push(n),
            None => return Err(fail("count", format!("each count must be from 1 to {MOST}, got {n}"))),
        }
    }
    let total: usize = counts.iter().product();
    if total > MOST {
        return Err(fail("count", format!("{total} copies: at most {MOST} in one array")));
    }
    let steps = raw.step.as_deref().unwrap_or_default();
    if steps.len() != counts.len() {
        let message = format!("needs one step [x, y, z] per count: {} counts, {} steps", counts.len(), steps.len());
        return Err(fail("step", message));
    }
    let mut vectors = Vec::new();
    for (&step, &n) in steps.iter().zip(&counts) {
        let v = DVec3::from_array(step);
        if !v.is_finite() || v.abs().max_element() > COORDINATE {
            return Err(fail("step", format!("must be finite, within ±{COORDINATE:e} m, got {}", show(v))));
        }
        if v == DVec3::ZERO && n > 1 {
            return Err(fail("step", format!("{n} copies one step of zero apart would coincide")));
        }
        vectors.push(v);
    }
    let copy = |flat: usize| {
        let (mut rest, mut suffix, mut offset) = (flat, String::new(), DVec3::ZERO);
        for (d, &n) in counts.iter().enumerate().rev() {
            let i = rest % n;
            rest /= n;
            suffix = format!("-{}{suffix}", i + 1);
            offset += vectors[d] * i as f64;
        }
        Copy { suffix, motion: Motion::translation(offset), key: "array".to_string() }
    };
    Ok((0..total).map(copy).collect())
}

/// The copies of `transforms`, each turned about its axis through its pivot, then moved.
fn listed(
    at: &Context,
    source: &str,
    transforms: &Spanned<Vec<RawTransform>>,
    centre: DVec3,
) -> Result<Vec<Copy>, SceneError> {
    let list = transforms.get_ref();
    let fail = |key: String, message: String| at.error(&key, format!("{}{message}", line(source, transforms)));
    if list.is_empty() || list.len() > MOST {
        return Err(fail("transforms".into(), format!("must list 1 to {MOST} transforms, got {}", list.len())));
    }
    let mut copies = Vec::new();
    for (k, t) in list.iter().enumerate() {
        let key = |what: &str| format!("transforms[{}].{what}", k + 1);
        let vector = |what: &str, v: Option<[f64; 3]>, default: DVec3| {
            let v = v.map_or(default, DVec3::from_array);
            match v.is_finite() && v.abs().max_element() <= COORDINATE {
                true => Ok(v),
                false => Err(fail(key(what), format!("must be finite, within ±{COORDINATE:e} m, got {}", show(v)))),
            }
        };
        let translate = vector("translate", t.translate, DVec3::ZERO)?;
        let pivot = vector("pivot", t.pivot, centre)?;
        let axis = vector("rotate_axis", t.rotate_axis, DVec3::Y)?
            .try_normalize()
            .ok_or_else(|| fail(key("rotate_axis"), "must be a non-zero vector".into()))?;
        let angle_deg = t.rotate_deg.unwrap_or(0.0);
        if !angle_deg.is_finite() {
            return Err(fail(key("rotate_deg"), format!("must be a finite number, got {}", number(angle_deg))));
        }
        let motion = Motion { axis, angle_deg, pivot, translate };
        copies.push(Copy { suffix: format!("-{}", k + 1), motion, key: key("rotate_axis") });
    }
    Ok(copies)
}
