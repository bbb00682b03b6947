//! The case file as written: serde structs that mirror the TOML tables key for key.
//!
//! Every struct denies unknown keys, so a misspelled key is an error. Values are not
//! checked here (that is `validate`'s job); this module only turns toml/serde errors
//! into [`SceneError`]s that name the file, the line, the table and the key.

use super::error::SceneError;
use serde::Deserialize;
use std::path::Path;

/// The whole case file.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawScene {
    pub scene: Option<RawSceneInfo>,
    pub discretization: Option<RawDiscretization>,
    pub solver: Option<RawSolver>,
    #[serde(default)]
    pub material: Vec<RawMaterial>,
    #[serde(default)]
    pub surface: Vec<RawSurface>,
    #[serde(default)]
    pub probe: Vec<super::probe::RawProbe>,
    #[serde(default)]
    pub observer: Vec<super::observer::RawObserver>,
    #[serde(default)]
    pub glare_grid: Vec<super::glare_grid::RawGlareGrid>,
    #[serde(default)]
    pub camera: Vec<RawCamera>,
    #[serde(default)]
    pub grid: Vec<super::grid::RawGrid>,
    #[serde(default)]
    pub luminaire: Vec<super::luminaire::RawLuminaire>,
    pub lighting: Option<super::light_scene::RawLighting>,
    #[serde(default)]
    pub light_scene: Vec<super::light_scene::RawLightScene>,
    pub sky: Option<super::sky::RawSky>,
    #[serde(default)]
    pub window: Vec<super::sky::RawWindow>,
}

/// `[scene]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawSceneInfo {
    pub name: Option<String>,
    pub description: Option<String>,
}

/// `[discretization]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawDiscretization {
    pub patch_size: f64,
    pub directions: Option<RawDirections>,
    pub kernel: Option<String>,
    pub root_size: Option<f64>,
    pub link_tolerance: Option<f64>,
    /// The old spelling: `method` for `kernel`; with `method = "hierarchical"`,
    /// `patch_size` the roots, `smallest` the finest leaves, `tolerance` the links'.
    pub method: Option<String>,
    pub tolerance: Option<f64>,
    pub smallest: Option<f64>,
}

/// `directions = 64` or `directions = "klems"`.
#[derive(Debug, Deserialize)]
#[serde(untagged)]
pub enum RawDirections {
    Count(u64),
    Name(String),
}

/// `[solver]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawSolver {
    pub method: Option<String>,
    pub tolerance: Option<f64>,
    pub max_iterations: Option<i64>,
}

/// `[[material]]`. `type` is kept as a string (checked by `validate`): a serde-tagged
/// enum would buffer the table and lose the position of a misspelled key.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawMaterial {
    pub name: String,
    #[serde(rename = "type")]
    pub model: String,
    pub reflectance: Option<f64>,
    pub transmittance: Option<f64>,
    pub specular: Option<f64>,
    pub exponent: Option<f64>,
    pub roughness: Option<f64>,
}

/// `[[surface]]`: the common keys plus every shape's keys, each optional.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawSurface {
    pub name: String,
    pub shape: String,
    pub material: String,
    pub two_sided: Option<bool>,
    pub inside: Option<bool>,
    pub emission: Option<RawEmission>,
    /// The group of sources an emitting surface is dimmed with (`light_scene.rs`).
    pub group: Option<serde_spanned::Spanned<String>>,
    #[serde(default, deserialize_with = "super::arrays::exact_opt")]
    pub origin: Option<[f64; 3]>,
    #[serde(default, deserialize_with = "super::arrays::exact_opt")]
    pub edge_u: Option<[f64; 3]>,
    #[serde(default, deserialize_with = "super::arrays::exact_opt")]
    pub edge_v: Option<[f64; 3]>,
    #[serde(default, deserialize_with = "super::arrays::exact_list")]
    pub vertices: Option<Vec<[f64; 3]>>,
    #[serde(default, deserialize_with = "super::arrays::exact_opt")]
    pub min: Option<[f64; 3]>,
    #[serde(default, deserialize_with = "super::arrays::exact_opt")]
    pub max: Option<[f64; 3]>,
    pub rotate_y_deg: Option<f64>,
    #[serde(default, deserialize_with = "super::arrays::exact_opt")]
    pub center: Option<[f64; 3]>,
    #[serde(default, deserialize_with = "super::arrays::exact_opt")]
    pub normal: Option<[f64; 3]>,
    pub radius: Option<f64>,
    pub file: Option<String>,
    pub scale: Option<f64>,
    #[serde(default, deserialize_with = "super::arrays::exact_opt")]
    pub translate: Option<[f64; 3]>,
    #[serde(default, deserialize_with = "super::arrays::exact_opt")]
    pub rotate_axis: Option<[f64; 3]>,
    pub rotate_deg: Option<f64>,
    /// A mesh's `usemtl` name → the `name` of a `[[material]]` (`obj.rs`).
    pub materials: Option<serde_spanned::Spanned<std::collections::BTreeMap<String, String>>>,
    /// A rectangle's or polygon's holes (`holes.rs`).
    pub holes: Option<serde_spanned::Spanned<Vec<super::holes::RawHole>>>,
    /// Copies of the surface on a lattice (`instances.rs`).
    pub array: Option<serde_spanned::Spanned<super::instances::RawArray>>,
    /// Copies of the surface, each moved and turned (`instances.rs`).
    pub transforms: Option<serde_spanned::Spanned<Vec<super::instances::RawTransform>>>,
}

/// `emission = { luminance = … }` or `emission = { flux = … }`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawEmission {
    pub luminance: Option<f64>,
    pub flux: Option<f64>,
}

/// `[[camera]]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawCamera {
    /// `name`: the camera's name.
    pub name: String,
    /// `position`: the eye, m.
    #[serde(deserialize_with = "super::arrays::exact")]
    pub position: [f64; 3],
    /// `look_at`: the point looked at, m.
    #[serde(deserialize_with = "super::arrays::exact")]
    pub look_at: [f64; 3],
    /// `up`: the image's upward direction (default `[0, 1, 0]`).
    #[serde(default, deserialize_with = "super::arrays::exact_opt")]
    pub up: Option<[f64; 3]>,
    /// `fov_deg`: the vertical field of view, degrees (default 40).
    pub fov_deg: Option<f64>,
    /// `resolution`: width and height, pixels (default `[512, 512]`).
    #[serde(default, deserialize_with = "super::arrays::exact_opt")]
    pub resolution: Option<[i64; 2]>,
    /// `samples`: primary rays per pixel (default 4).
    pub samples: Option<i64>,
}

/// Parses case text into the raw tables.
pub fn parse(path: &Path, source: &str) -> Result<RawScene, SceneError> {
    toml::from_str(source).map_err(|e| locate(path, source, &e))
}

/// Turns a toml/serde error into a [`SceneError`] naming the line, table and key.
fn locate(path: &Path, source: &str, error: &toml::de::Error) -> SceneError {
    let message = error.message();
    let Some(mut at) = error.span().map(|span| span.start.min(source.len())) else {
        return SceneError::new(path, "", quoted_field(message).unwrap_or(""), message);
    };
    while !source.is_char_boundary(at) {
        at -= 1;
    }
    let line = source[..at].matches('\n').count() + 1;
    let key = key_at(source, at, message);
    let table = enclosing_table(source, at);
    SceneError::new(path, table, key, format!("line {line}: {message}"))
}

/// The field named by serde's "unknown field `x`" and "missing field `x`" messages.
fn quoted_field(message: &str) -> Option<&str> {
    let rest = ["unknown field `", "missing field `"].iter().find_map(|prefix| message.strip_prefix(prefix))?;
    rest.split('`').next()
}

/// The key the error at byte `at` is about: the field serde names, or the `key =` just
/// before `at`, prefixed by the line's leading key inside inline tables
/// (`emission.luminance`); for a continuation line of a multi-line array, the key the
/// array belongs to; none for a header line (the table is the subject).
fn key_at(source: &str, at: usize, message: &str) -> String {
    let (line_start, line_end) = line_around(source, at);
    let head = &source[line_start..at];
    let inner = quoted_field(message).or_else(|| nearest_key(head));
    match (leading_key(head), inner) {
        (Some(leading), Some(inner)) if leading != inner => format!("{leading}.{inner}"),
        (Some(leading), _) => leading.to_string(),
        (None, Some(inner)) => inner.to_string(),
        (None, None) if header(&source[line_start..line_end]).is_some() => String::new(),
        (None, None) => continued_key(&source[..line_start]),
    }
}

/// The start and end (before the newline) of the line holding byte `at`.
fn line_around(source: &str, at: usize) -> (usize, usize) {
    let start = source[..at].rfind('\n').map_or(0, |i| i + 1);
    let end = source[at..].find('\n').map_or(source.len(), |i| at + i);
    (start, end)
}

/// The leading key of the nearest line above (within the same table) that has one.
fn continued_key(above: &str) -> String {
    above.lines().rev().take_while(|line| header(line).is_none()).find_map(leading_key).unwrap_or("").to_string()
}

/// `key` in a line that starts with `key =`.
fn leading_key(line: &str) -> Option<&str> {
    let (key, _) = line.split_once('=')?;
    let key = key.trim().trim_matches('"');
    is_bare_key(key).then_some(key)
}

/// The last `key` in `… key =` at the end of `head`.
fn nearest_key(head: &str) -> Option<&str> {
    let before = head.trim_end().strip_suffix('=')?.trim_end();
    // The character before the key may be several bytes long (issue 18: a `ρ` there).
    let start = before.char_indices().rev().find(|(_, c)| !is_key_char(*c)).map_or(0, |(i, c)| i + c.len_utf8());
    let key = &before[start..];
    is_bare_key(key).then_some(key)
}

fn is_key_char(c: char) -> bool {
    c.is_ascii_alphanumeric() || c == '_' || c == '-'
}

fn is_bare_key(key: &str) -> bool {
    !key.is_empty() && key.chars().all(is_key_char)
}

/// The header enclosing byte `at` (the header itself if `at` is on it), e.g. `[solver]`,
/// or `[[surface]] #2` for the second `[[surface]]`; empty at the top level.
fn enclosing_table(source: &str, at: usize) -> String {
    let (_, line_end) = line_around(source, at);
    let headers: Vec<Header> = source[..line_end].lines().filter_map(header).collect();
    match headers.last() {
        None => String::new(),
        Some(&Header { name, array: false }) => format!("[{name}]"),
        Some(last) => {
            let index = headers.iter().filter(|h| *h == last).count();
            format!("[[{}]] #{index}", last.name)
        }
    }
}

/// A table header line: `[name]` or (array) `[[name]]`.
#[derive(PartialEq)]
struct Header<'a> {
    name: &'a str,
    array: bool,
}

/// Reads a `[name]` or `[[name]]` header line (a comment may follow it).
fn header(line: &str) -> Option<Header<'_>> {
    let line = line.split('#').next().unwrap_or("").trim();
    let inner = line.strip_prefix('[')?.strip_suffix(']')?;
    let array_inner = inner.strip_prefix('[').and_then(|s| s.strip_suffix(']'));
    let name = array_inner.unwrap_or(inner).trim();
    let starts_like_a_name = name.starts_with(|c: char| c.is_ascii_alphabetic() || c == '_');
    let name_chars = name.chars().all(|c| is_key_char(c) || c == '.' || c == ' ');
    (starts_like_a_name && name_chars).then_some(Header { name, array: array_inner.is_some() })
}
