//! `[[probe]]` tables: point sensors as written and as validated. Four kinds (issue 17,
//! item 7): a point sensor of luminance and illuminance (`"point"`, the default), a
//! luminance meter (`"luminance_meter"`: the mean luminance in a cone), and the
//! cylindrical and semi-cylindrical illuminance of lighting standards (`"cylindrical"`,
//! `"semi_cylindrical"`, EN 12464-1 and EN 13201-2). What each reads is
//! `crate::readout::probe`.

use super::check::{Context, REL_TOL, show, unique_names};
use super::error::SceneError;
use glam::DVec3;
use serde::Deserialize;
use std::path::Path;

/// `[[probe]]` as written.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawProbe {
    pub name: String,
    pub kind: Option<String>,
    #[serde(deserialize_with = "super::arrays::exact")]
    pub position: [f64; 3],
    #[serde(default, deserialize_with = "super::arrays::exact_opt")]
    pub normal: Option<[f64; 3]>,
    #[serde(default, deserialize_with = "super::arrays::exact_opt")]
    pub direction: Option<[f64; 3]>,
    pub fov_deg: Option<f64>,
    #[serde(default, deserialize_with = "super::arrays::exact_opt")]
    pub axis: Option<[f64; 3]>,
}

/// `[[probe]]`: a point sensor.
#[derive(Debug, Clone, PartialEq)]
pub struct Probe {
    /// The probe's name, unique in the scene.
    pub name: String,
    /// Where it reads, m.
    pub position: DVec3,
    /// Unit vector: the receiving side of a point sensor, the viewing direction of a
    /// luminance meter, the axis of a cylindrical probe, the direction the curved side of
    /// a semi-cylindrical probe faces (across its axis).
    pub normal: DVec3,
    /// What it reads.
    pub kind: ProbeKind,
}

impl Probe {
    /// A point sensor facing `normal` (unit).
    pub fn point(name: &str, position: DVec3, normal: DVec3) -> Probe {
        Probe { name: name.to_string(), position, normal, kind: ProbeKind::Point }
    }
}

/// The closed set of probe kinds.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ProbeKind {
    /// Luminance and illuminance on a receiver facing `normal`.
    Point,
    /// The mean luminance within a cone of full angle `fov_deg` about `normal`.
    LuminanceMeter {
        /// The full angle of the cone, degrees.
        fov_deg: f64,
    },
    /// The mean illuminance on a small cylinder about the axis `normal`.
    Cylindrical,
    /// The mean illuminance on the curved side of a small half cylinder about the unit
    /// `axis`, facing `normal` (perpendicular to the axis).
    SemiCylindrical {
        /// The unit axis of the half cylinder.
        axis: DVec3,
    },
}

impl ProbeKind {
    /// The names of `kind`.
    pub const NAMES: [&'static str; 4] = ["point", "luminance_meter", "cylindrical", "semi_cylindrical"];

    /// As written in `kind`.
    pub fn name(&self) -> &'static str {
        match self {
            ProbeKind::Point => Self::NAMES[0],
            ProbeKind::LuminanceMeter { .. } => Self::NAMES[1],
            ProbeKind::Cylindrical => Self::NAMES[2],
            ProbeKind::SemiCylindrical { .. } => Self::NAMES[3],
        }
    }
}

/// Every kind and the keys it takes besides `name`, `kind` and `position`.
const KEYS: [(&str, &[&str]); 4] = [
    ("point", &["normal"]),
    ("luminance_meter", &["direction", "fov_deg"]),
    ("cylindrical", &["axis"]),
    ("semi_cylindrical", &["axis", "direction"]),
];

/// The vertical, the default axis of the cylindrical probes.
const UP: [f64; 3] = [0.0, 1.0, 0.0];

pub(super) fn probes(path: &Path, raw: &[RawProbe]) -> Result<Vec<Probe>, SceneError> {
    unique_names(path, "probe", raw.iter().map(|p| p.name.as_str()))?;
    raw.iter().enumerate().map(|(index, p)| probe(&Context::item(path, "probe", &p.name, index), p)).collect()
}

fn probe(at: &Context, p: &RawProbe) -> Result<Probe, SceneError> {
    let name = p.kind.as_deref().unwrap_or("point");
    let Some(&(_, keys)) = KEYS.iter().find(|(kind, _)| *kind == name) else {
        let known: Vec<String> = ProbeKind::NAMES.iter().map(|n| format!("\"{n}\"")).collect();
        return Err(at.error("kind", format!("unknown probe kind \"{name}\"; known: {}", known.join(", "))));
    };
    let given = [
        ("normal", p.normal.is_some()),
        ("direction", p.direction.is_some()),
        ("fov_deg", p.fov_deg.is_some()),
        ("axis", p.axis.is_some()),
    ];
    if let Some((stray, _)) = given.iter().find(|(key, set)| *set && !keys.contains(key)) {
        return Err(at.error(stray, format!("a \"{name}\" probe takes only {}", keys.join(", "))));
    }
    let required = |key: &str, value: Option<[f64; 3]>| {
        let value = value.ok_or_else(|| at.error(key, format!("a \"{name}\" probe needs `{key}`")))?;
        at.direction(key, value)
    };
    let position = at.place("position", p.position)?;
    let (normal, kind) = match name {
        "point" => (required("normal", p.normal)?, ProbeKind::Point),
        "luminance_meter" => {
            let fov_deg = at.finite("fov_deg", p.fov_deg.unwrap_or(1.0))?;
            if fov_deg <= 0.0 || fov_deg > 180.0 {
                return Err(at.error("fov_deg", format!("must be greater than 0 and at most 180, got {fov_deg}")));
            }
            (required("direction", p.direction)?, ProbeKind::LuminanceMeter { fov_deg })
        }
        "cylindrical" => (at.direction("axis", p.axis.unwrap_or(UP))?, ProbeKind::Cylindrical),
        _ => {
            let axis = at.direction("axis", p.axis.unwrap_or(UP))?;
            let direction = required("direction", p.direction)?;
            let across = Some(direction - axis * direction.dot(axis)).filter(|a| a.length() > REL_TOL);
            let message = || format!("must not be parallel to the axis {}", show(axis));
            let across = across.ok_or_else(|| at.error("direction", message()))?.normalize();
            (across, ProbeKind::SemiCylindrical { axis })
        }
    };
    Ok(Probe { name: p.name.clone(), position, normal, kind })
}
