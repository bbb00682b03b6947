//! Light scenes (`[[light_scene]]`), the groups of sources they dim (`group` keys of
//! `[[luminaire]]` and `[[surface]]`) and the maintenance factor (`[lighting]`), as written
//! and as validated.
//!
//! The field is linear in the sources (`docs/design.md` §1: `L = (I − K)⁻¹ L0`, `L0 = L_e + B·D`
//! linear in every emission and intensity), so a light scene is a weighted sum of one field
//! per group (`crate::study::solve_light_scenes`). A source without `group` is in the group
//! [`DEFAULT_GROUP`]; a group exists when a source names it. A light scene gives each group
//! it lights a factor from 0 (off) to 1 (full output), or `true` (1) and `false` (0);
//! groups it does not name are off. The maintenance factor multiplies every electric source
//! of the case (the `[[luminaire]]`s, parallel light included, and emitting surfaces) before
//! anything else sees it, so every solve, light scene and Monte Carlo reference uses the
//! maintained output. Daylight is not electric light: the openings have their own glazing
//! maintenance factor (`[[window]] maintenance_factor`, `sky.rs`), and the sun of `[sky]`
//! none (`docs/daylight.md`).

use super::check::{Context, line};
use super::error::SceneError;
use crate::geometry::{Emission, Surface};
use crate::luminaire::{Luminaire, LuminaireKind};
use serde::Deserialize;
use serde_spanned::Spanned;
use std::collections::BTreeMap;
use std::path::Path;

/// The group of every source that names none.
pub const DEFAULT_GROUP: &str = "default";

/// `[lighting]` as written.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawLighting {
    pub maintenance_factor: Option<Spanned<f64>>,
}

/// `[[light_scene]]` as written.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawLightScene {
    pub name: Spanned<String>,
    #[serde(default)]
    pub groups: BTreeMap<String, Spanned<RawFactor>>,
}

/// A group's level in a light scene: a dimming factor, or on (1) / off (0).
#[derive(Debug, Deserialize)]
#[serde(untagged)]
pub enum RawFactor {
    On(bool),
    Factor(f64),
}

/// The sources' groups, the light scenes and the maintenance factor of a case.
#[derive(Debug, Clone, PartialEq)]
pub struct Lighting {
    /// Already applied to every source of the scene (`[lighting] maintenance_factor`).
    pub maintenance_factor: f64,
    /// In order of first use: surfaces in file order, then luminaires.
    pub groups: Vec<LightGroup>,
    /// The `[[light_scene]]` tables, in file order.
    pub scenes: Vec<LightScene>,
}

impl Default for Lighting {
    /// No groups, no light scenes, maintenance factor 1.
    fn default() -> Lighting {
        Lighting { maintenance_factor: 1.0, groups: Vec::new(), scenes: Vec::new() }
    }
}

/// Sources dimmed together.
#[derive(Debug, Clone, PartialEq)]
pub struct LightGroup {
    /// The group's name (`group = …` of its sources; [`DEFAULT_GROUP`] for none).
    pub name: String,
    /// Indices into the scene's luminaires.
    pub luminaires: Vec<usize>,
    /// Indices into the scene's surfaces (each has an `emission`).
    pub surfaces: Vec<usize>,
}

/// `[[light_scene]]`: a factor for every group.
#[derive(Debug, Clone, PartialEq)]
pub struct LightScene {
    /// Letters, digits, `-` and `_`: it names files and HDF5 groups.
    pub name: String,
    /// One per group of [`Lighting::groups`], from 0 (off) to 1.
    pub factors: Vec<f64>,
}

/// What the lighting tables of a case refer to: the sources, validated, and the `group`
/// each names (one per surface and per luminaire).
pub(super) struct Sources<'a> {
    pub surface_groups: Vec<Option<Spanned<String>>>,
    pub luminaire_groups: Vec<Option<Spanned<String>>>,
    pub surfaces: &'a mut [Surface],
    pub luminaires: &'a mut [Luminaire],
    /// The first `electric` luminaires are the `[[luminaire]]` tables' (the rest daylight).
    pub electric: usize,
}

/// Validates `[lighting]`, the `group` keys and the `[[light_scene]]` tables of `path`
/// (whose text is `source`, for line numbers), and applies the maintenance factor.
pub(super) fn lighting(
    path: &Path,
    source: &str,
    raw: Option<RawLighting>,
    scenes: &[RawLightScene],
    sources: Sources,
) -> Result<Lighting, SceneError> {
    let maintenance_factor = maintenance_factor(path, source, raw)?;
    let groups = groups(path, source, &sources)?;
    let scenes = scenes
        .iter()
        .enumerate()
        .map(|(i, s)| light_scene(path, source, (i, s), &scenes[..i], &groups))
        .collect::<Result<_, _>>()?;
    sources.surfaces.iter_mut().for_each(|s| s.emission = s.emission.map(|e| dim(e, maintenance_factor)));
    for l in sources.luminaires[..sources.electric].iter_mut() {
        match &mut l.kind {
            LuminaireKind::Point(p) => p.multiplier *= maintenance_factor,
            LuminaireKind::Parallel { illuminance, .. } => *illuminance *= maintenance_factor,
            LuminaireKind::Window { .. } => {}
        }
    }
    Ok(Lighting { maintenance_factor, groups, scenes })
}

fn dim(emission: Emission, factor: f64) -> Emission {
    match emission {
        Emission::Luminance(l) => Emission::Luminance(l * factor),
        Emission::Flux(f) => Emission::Flux(f * factor),
    }
}

fn maintenance_factor(path: &Path, source: &str, raw: Option<RawLighting>) -> Result<f64, SceneError> {
    let Some(value) = raw.and_then(|r| r.maintenance_factor) else { return Ok(1.0) };
    let mf = *value.get_ref();
    if mf > 0.0 && mf <= 1.0 {
        return Ok(mf);
    }
    let message = format!(
        "{}must be greater than 0 and at most 1 (the share of the new output kept), got {mf}",
        line(source, &value)
    );
    Err(Context::new(path, "[lighting]").error("maintenance_factor", message))
}

/// The groups named by the sources, each source in exactly one.
fn groups(path: &Path, source: &str, sources: &Sources) -> Result<Vec<LightGroup>, SceneError> {
    let mut groups: Vec<LightGroup> = Vec::new();
    let mut find = |name: &str| match groups.iter().position(|g| g.name == name) {
        Some(i) => i,
        None => {
            groups.push(LightGroup { name: name.to_string(), luminaires: Vec::new(), surfaces: Vec::new() });
            groups.len() - 1
        }
    };
    let mut surface_groups = Vec::new();
    for (index, (group, surface)) in sources.surface_groups.iter().zip(sources.surfaces.iter()).enumerate() {
        let at = Context::item(path, "surface", &surface.name, index);
        let name = group_name(&at, source, group.as_ref())?;
        match (surface.emission, group.as_ref()) {
            (Some(_), _) => surface_groups.push((find(name), index)),
            (None, Some(group)) => {
                let message =
                    format!("{}the surface has no `emission`, so it is in no group of sources", line(source, group));
                return Err(at.error("group", message));
            }
            (None, None) => {}
        }
    }
    let mut luminaire_groups = Vec::new();
    for (index, (group, luminaire)) in sources.luminaire_groups.iter().zip(sources.luminaires.iter()).enumerate() {
        let at = Context::item(path, "luminaire", &luminaire.name, index);
        luminaire_groups.push((find(group_name(&at, source, group.as_ref())?), index));
    }
    for (g, s) in surface_groups {
        groups[g].surfaces.push(s);
    }
    for (g, l) in luminaire_groups {
        groups[g].luminaires.push(l);
    }
    Ok(groups)
}

/// The `group` a source names (non-empty), or [`DEFAULT_GROUP`].
fn group_name<'a>(at: &Context, source: &str, group: Option<&'a Spanned<String>>) -> Result<&'a str, SceneError> {
    match group {
        None => Ok(DEFAULT_GROUP),
        Some(g) if g.get_ref().is_empty() => Err(at.error("group", format!("{}must not be empty", line(source, g)))),
        Some(g) => Ok(g.get_ref()),
    }
}

/// The `index`-th light scene, after the `earlier` ones.
fn light_scene(
    path: &Path,
    source: &str,
    (index, raw): (usize, &RawLightScene),
    earlier: &[RawLightScene],
    groups: &[LightGroup],
) -> Result<LightScene, SceneError> {
    let name = raw.name.get_ref();
    let at = Context::item(path, "light_scene", name, index);
    if name.is_empty() {
        return Err(at.error("name", format!("{}must not be empty", line(source, &raw.name))));
    }
    if let Some(first) = earlier.iter().position(|s| s.name.get_ref() == name) {
        let message =
            format!("{}duplicate name \"{name}\" (also [[light_scene]] #{})", line(source, &raw.name), first + 1);
        return Err(at.error("name", message));
    }
    if !name.chars().all(|c| c.is_ascii_alphanumeric() || c == '-' || c == '_') {
        let message = format!(
            "{}a light scene's name names its files and HDF5 group: letters, digits, '-' and '_' only, got \"{name}\"",
            line(source, &raw.name)
        );
        return Err(at.error("name", message));
    }
    let mut factors = vec![0.0; groups.len()];
    for (group, value) in &raw.groups {
        let key = format!("groups.{group}");
        let Some(g) = groups.iter().position(|g| &g.name == group) else {
            let known: Vec<String> = groups.iter().map(|g| format!("\"{}\"", g.name)).collect();
            let message = format!(
                "{}unknown group \"{group}\"; the case's groups (`group` keys of [[luminaire]] and [[surface]], \
                 \"{DEFAULT_GROUP}\" for sources without one): {}",
                line(source, value),
                known.join(", ")
            );
            return Err(at.error(&key, message));
        };
        factors[g] = match *value.get_ref() {
            RawFactor::On(on) => f64::from(u8::from(on)),
            RawFactor::Factor(f) if (0.0..=1.0).contains(&f) => f,
            RawFactor::Factor(f) => {
                let message = format!(
                    "{}a dimming factor is from 0 (off) to 1 (full output), got {f}{}",
                    line(source, value),
                    if f > 1.0 && f <= 100.0 { " (a percentage? write it as a fraction)" } else { "" }
                );
                return Err(at.error(&key, message));
            }
        };
    }
    if factors.iter().all(|&f| f == 0.0) {
        let message = format!(
            "{}turns every group off ({}): nothing would light it; give a group a factor above 0",
            line(source, &raw.name),
            groups.iter().map(|g| format!("\"{}\"", g.name)).collect::<Vec<_>>().join(", ")
        );
        return Err(at.error("groups", message));
    }
    Ok(LightScene { name: name.clone(), factors })
}
