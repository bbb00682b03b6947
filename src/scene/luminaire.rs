//! `[[luminaire]]` tables: light sources that are not surfaces (photometric point sources
//! and parallel light), as written and as validated; a table with `array` expands into the
//! members of the array (`luminaire_array.rs`).
//!
//! Owns the keys of each luminaire type, their rules, and reading the photometric file
//! (relative to the case file's folder; a bad file's error names the file, its line and
//! what was expected there). The runtime placement and the source term are in
//! `crate::luminaire`; the distributions in `crate::photometry`.

use super::check::{Context, MAGNITUDE, unique_names};
use super::error::SceneError;
use super::files::CaseFiles;
use super::luminaire_array::{Member, RawArray, group_by, members};
use crate::luminaire::{Luminaire, LuminaireKind, PointLuminaire};
use crate::photometry::{Distribution, PhotometryError, parse_ies, parse_ldt};
use crate::sky::BeamGlass;
use glam::DVec3;
use serde::Deserialize;
use serde_spanned::Spanned;
use std::collections::HashMap;
use std::path::Path;

/// `[[luminaire]]` as written.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawLuminaire {
    pub name: String,
    #[serde(rename = "type")]
    pub kind: String,
    #[serde(default, deserialize_with = "super::arrays::exact_opt")]
    pub position: Option<[f64; 3]>,
    #[serde(default, deserialize_with = "super::arrays::exact_opt")]
    pub aim: Option<[f64; 3]>,
    pub rotate_deg: Option<f64>,
    pub multiplier: Option<f64>,
    pub flux: Option<f64>,
    pub intensity: Option<f64>,
    pub file: Option<String>,
    #[serde(default, deserialize_with = "super::arrays::exact_opt")]
    pub direction: Option<[f64; 3]>,
    pub illuminance: Option<f64>,
    /// The group of sources it is dimmed with (`light_scene.rs`).
    pub group: Option<Spanned<String>>,
    /// Places a rectangular array of this luminaire (`luminaire_array.rs`).
    pub array: Option<Spanned<RawArray>>,
}

/// Every luminaire type and the keys it takes besides `name` and `type`.
const TYPES: [(&str, &[&str]); 5] = [
    ("isotropic", &["position", "flux", "intensity", "multiplier", "array"]),
    ("lambertian", &["position", "intensity", "aim", "multiplier", "array"]),
    ("ies", &["position", "file", "aim", "rotate_deg", "multiplier", "array"]),
    ("eulumdat", &["position", "file", "aim", "rotate_deg", "multiplier", "array"]),
    ("parallel", &["direction", "illuminance"]),
];

/// Validates the `[[luminaire]]` tables of the case file `path` (whose text is `source`),
/// an array expanded into its members: the luminaires, and for each the `group` it is
/// dimmed with (its table's, or its row's, column's or own by the array's `group_by`).
pub fn luminaires(
    path: &Path,
    source: &str,
    raw: &[RawLuminaire],
    files: &CaseFiles,
) -> Result<(Vec<Luminaire>, Vec<Group>), SceneError> {
    unique_names(path, "luminaire", raw.iter().map(|l| l.name.as_str()))?;
    let mut names: HashMap<String, usize> = raw.iter().enumerate().map(|(i, l)| (l.name.clone(), i)).collect();
    let (mut placed, mut groups) = (Vec::new(), Vec::new());
    for (index, l) in raw.iter().enumerate() {
        let at = Context::item(path, "luminaire", &l.name, index);
        for (luminaire, group) in expand(&at, source, l, kind(&at, l, files)?)? {
            let earlier = if l.array.is_some() { names.insert(luminaire.name.clone(), index) } else { None };
            if let Some(other) = earlier {
                let message = format!(
                    "the array's luminaire \"{}\" has the name of another luminaire ([[luminaire]] #{})",
                    luminaire.name,
                    other + 1
                );
                return Err(at.error("name", message));
            }
            placed.push(luminaire);
            groups.push(group);
        }
    }
    Ok((placed, groups))
}

/// The `group` a luminaire is dimmed with, as written (or made by an array's `group_by`).
pub type Group = Option<Spanned<String>>;

/// The luminaire of table `l` with its `kind`, or the members of its array, each with its
/// group.
fn expand(
    at: &Context,
    source: &str,
    l: &RawLuminaire,
    kind: LuminaireKind,
) -> Result<Vec<(Luminaire, Group)>, SceneError> {
    let (Some(array), LuminaireKind::Point(point)) = (&l.array, &kind) else {
        return Ok(vec![(Luminaire { name: l.name.clone(), kind }, l.group.clone())]);
    };
    let members = members(at, source, array, l.position.map(|_| point.position))?;
    let by = group_by(at, source, array)?;
    let stem = l.group.as_ref().map_or(l.name.as_str(), |g| g.get_ref().as_str());
    let span = l.group.as_ref().map_or(array.span(), |g| g.span());
    let member = |m: Member| {
        let group = by.group_of(stem, m.row, m.column).map(|name| Spanned::new(span.clone(), name));
        let luminaire = Luminaire {
            name: format!("{}{}", l.name, m.suffix),
            kind: LuminaireKind::Point(PointLuminaire { position: m.position, ..point.clone() }),
        };
        (luminaire, group.or_else(|| l.group.clone()))
    };
    Ok(members.into_iter().map(member).collect())
}

fn kind(at: &Context, l: &RawLuminaire, files: &CaseFiles) -> Result<LuminaireKind, SceneError> {
    let Some(&(name, keys)) = TYPES.iter().find(|(name, _)| *name == l.kind) else {
        let known: Vec<String> = TYPES.iter().map(|(n, _)| format!("\"{n}\"")).collect();
        return Err(at.error("type", format!("unknown luminaire type \"{}\"; known: {}", l.kind, known.join(", "))));
    };
    let given = [
        ("position", l.position.is_some()),
        ("aim", l.aim.is_some()),
        ("rotate_deg", l.rotate_deg.is_some()),
        ("multiplier", l.multiplier.is_some()),
        ("flux", l.flux.is_some()),
        ("intensity", l.intensity.is_some()),
        ("file", l.file.is_some()),
        ("direction", l.direction.is_some()),
        ("illuminance", l.illuminance.is_some()),
        ("array", l.array.is_some()),
    ];
    if let Some((stray, _)) = given.iter().find(|(key, set)| *set && !keys.contains(key)) {
        return Err(at.error(stray, format!("a \"{name}\" luminaire takes only {}", keys.join(", "))));
    }
    let required = |key: &str, value: Option<f64>| {
        value.ok_or_else(|| at.error(key, format!("a \"{name}\" luminaire needs `{key}`")))
    };
    if name == "parallel" {
        let direction = at.direction(
            "direction",
            l.direction.ok_or_else(|| {
                at.error("direction", "a \"parallel\" luminaire needs `direction` (the direction the light travels)")
            })?,
        )?;
        let illuminance = at.positive("illuminance", required("illuminance", l.illuminance)?)?;
        let illuminance = at.magnitude("illuminance", illuminance, " lx")?;
        // the windows' glass is attached with the [sky]'s (`sky::glaze`)
        return Ok(LuminaireKind::Parallel { direction, illuminance, glass: BeamGlass::default() });
    }
    // An array over a rectangle places its members itself (`luminaire_array.rs`).
    let position = match (l.position, &l.array) {
        (Some(p), _) => at.place("position", p)?,
        (None, Some(_)) => DVec3::ZERO,
        (None, None) => return Err(at.error("position", format!("a \"{name}\" luminaire needs `position`"))),
    };
    let aim = at.direction("aim", l.aim.unwrap_or([0.0, -1.0, 0.0]))?;
    let rotate_deg = at.finite("rotate_deg", l.rotate_deg.unwrap_or(0.0))?;
    let multiplier = at.positive("multiplier", l.multiplier.unwrap_or(1.0))?;
    let multiplier = at.magnitude("multiplier", multiplier, "")?;
    let (distribution, file) = match name {
        "isotropic" => (isotropic(at, l)?, None),
        "lambertian" => {
            let peak = at.positive("intensity", required("intensity", l.intensity)?)?;
            (Distribution::Lambertian { peak: at.magnitude("intensity", peak, " cd")? }, None)
        }
        _ => {
            let given =
                l.file.as_deref().ok_or_else(|| at.error("file", format!("a \"{name}\" luminaire needs `file`")))?;
            if given.is_empty() {
                return Err(at.error("file", "must not be empty"));
            }
            let file = at.file.parent().unwrap_or(Path::new("")).join(given);
            let text = files.read(&file).map(|bytes| String::from_utf8_lossy(&bytes).into_owned()).map_err(|e| {
                at.error("file", PhotometryError::whole(&file, format!("cannot read the file: {e}")).to_string())
            })?;
            let read = if name == "ies" { parse_ies(&file, &text) } else { parse_ldt(&file, &text) };
            let table = read.map_err(|e| at.error("file", e.to_string()))?;
            let flux = table.flux() * multiplier;
            if flux.is_nan() || flux > MAGNITUDE {
                let message = format!(
                    "out of range: the file's intensities integrate to {:e} lm, times `multiplier` {multiplier:e}, \
                     more than {MAGNITUDE:e} lm",
                    table.flux()
                );
                return Err(at.error("file", message));
            }
            (Distribution::Table(Box::new(table)), Some(file))
        }
    };
    Ok(LuminaireKind::Point(PointLuminaire { position, aim, rotate_deg, multiplier, distribution, file }))
}

/// An isotropic source: `flux` (lm) or `intensity` (cd), exactly one.
fn isotropic(at: &Context, l: &RawLuminaire) -> Result<Distribution, SceneError> {
    let intensity = match (l.flux, l.intensity) {
        (Some(flux), None) => at.magnitude("flux", at.positive("flux", flux)?, " lm")? / (4.0 * std::f64::consts::PI),
        (None, Some(i)) => at.magnitude("intensity", at.positive("intensity", i)?, " cd")?,
        (Some(_), Some(_)) => return Err(at.error("flux", "give `flux` or `intensity`, not both")),
        (None, None) => {
            return Err(at.error("flux", "an \"isotropic\" luminaire needs `flux` (lm) or `intensity` (cd)"));
        }
    };
    Ok(Distribution::Isotropic { intensity })
}
