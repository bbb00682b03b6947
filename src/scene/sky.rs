//! `[sky]` and `[[window]]`: the sky, the sun and the ground outside, and the openings
//! that let them in, as written and as validated (`docs/daylight.md`).
//!
//! Owns the keys and rules of both tables. Each `[[window]]` becomes a luminaire of kind
//! `Window` (the sky and ground seen through it, times the window's `maintenance_factor`:
//! BRE's and CIBSE's glazing maintenance factor, so the daylight factor scales by it while
//! `E_h` outside does not); `sun_illuminance` adds the sun as a parallel luminaire named
//! `"sun"`. The sun, and every other parallel luminaire, passes the windows' glass and dirt
//! where it crosses them (`τ(θ) M`, `crate::sky::BeamGlass`). The luminance model is `crate::sky`.

use super::check::{Context, REL_TOL, show, unique_names};
use super::error::SceneError;
use crate::geometry::ConvexPolygon;
use crate::luminaire::{Luminaire, LuminaireKind};
use crate::sky::{
    BeamGlass, Brightness, Distribution, Fresnel, Glazing, Opening, Pane, SiteTime, Sky, SunPosition, day_of_year,
};
use glam::DVec3;
use serde::Deserialize;
use std::path::Path;

/// `[sky]` as written.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawSky {
    #[serde(rename = "type")]
    pub kind: RawSkyType,
    pub sun_altitude_deg: Option<f64>,
    pub sun_azimuth_deg: Option<f64>,
    pub latitude_deg: Option<f64>,
    pub longitude_deg: Option<f64>,
    pub date: Option<String>,
    pub time: Option<String>,
    pub timezone_h: Option<f64>,
    pub zenith_luminance: Option<f64>,
    pub horizontal_illuminance: Option<f64>,
    pub ground_reflectance: Option<f64>,
    pub sun_illuminance: Option<f64>,
    #[serde(default, deserialize_with = "super::arrays::exact_opt")]
    pub north: Option<[f64; 3]>,
}

/// `type = 12` or `type = "overcast"`.
#[derive(Debug, Deserialize)]
#[serde(untagged)]
pub enum RawSkyType {
    Number(i64),
    Name(String),
}

/// `[[window]]` as written: a rectangle (parallelogram) opening, by its corner and edges or
/// by its place in a wall (`window_place.rs`), glazed when `glass` or
/// `transmittance` is given, with a maintenance factor for the dirt on it.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawWindow {
    pub name: String,
    #[serde(default, deserialize_with = "super::arrays::exact_opt")]
    pub origin: Option<[f64; 3]>,
    #[serde(default, deserialize_with = "super::arrays::exact_opt")]
    pub edge_u: Option<[f64; 3]>,
    #[serde(default, deserialize_with = "super::arrays::exact_opt")]
    pub edge_v: Option<[f64; 3]>,
    /// The rectangle `[[surface]]` the window is cut into (`window_place.rs`).
    pub wall: Option<serde_spanned::Spanned<String>>,
    /// In its `wall`: the window's corner, m along the wall's `edge_u` and `edge_v`.
    #[serde(default, deserialize_with = "super::arrays::exact_opt")]
    pub at: Option<[f64; 2]>,
    /// In its `wall`: the window's width and height, m along `edge_u` and `edge_v`.
    #[serde(default, deserialize_with = "super::arrays::exact_opt")]
    pub size: Option<[f64; 2]>,
    /// The glass model (none: Fresnel panes if `transmittance` is given, else unglazed).
    pub glass: Option<RawGlass>,
    /// Fresnel panes: the normal transmittance of one pane.
    pub transmittance: Option<f64>,
    pub panes: Option<i64>,
    pub refractive_index: Option<f64>,
    /// The glazing maintenance factor (dirt), in (0, 1]: the share of the light it keeps.
    pub maintenance_factor: Option<f64>,
}

/// `glass = "fresnel"` or `glass = "cie171"`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum RawGlass {
    Fresnel,
    Cie171,
}

/// The horizontal illuminance of the sky when neither brightness key is given, lx.
pub const DEFAULT_HORIZONTAL_ILLUMINANCE: f64 = 10_000.0;
/// The glass's refractive index when `refractive_index` is not given.
pub const DEFAULT_REFRACTIVE_INDEX: f64 = 1.52;
/// The ground's reflectance when `ground_reflectance` is not given.
pub const DEFAULT_GROUND_REFLECTANCE: f64 = 0.2;

/// The sky of `[sky]` (if any), the luminaires it brings (one per `[[window]]`, each at its
/// `placed` corner and edges, and the sun when `sun_illuminance` is given) and the windows'
/// glass, which the sun's beam and any other parallel light crossing them pass ([`glaze`]).
pub(super) fn daylight(
    path: &Path,
    raw: Option<&RawSky>,
    windows: &[RawWindow],
    placed: &[[DVec3; 3]],
) -> Result<(Option<Sky>, Vec<Luminaire>, BeamGlass), SceneError> {
    let Some(raw) = raw else {
        return match windows.first() {
            None => Ok((None, Vec::new(), BeamGlass::default())),
            Some(w) => Err(Context::item(path, "window", &w.name, 0)
                .error("", "a [[window]] lets the sky in: the case needs a [sky] table")),
        };
    };
    let at = Context::new(path, "[sky]");
    let distribution = match &raw.kind {
        RawSkyType::Number(n) => u8::try_from(*n).ok().and_then(|t| Distribution::parse(&t.to_string())),
        RawSkyType::Name(name) => Distribution::parse(name),
    }
    .ok_or_else(|| at.error("type", format!("unknown sky type; give {}", Distribution::NAMES)))?;
    let north = at.direction("north", raw.north.unwrap_or([0.0, 0.0, -1.0]))?;
    if north.y.abs() > REL_TOL {
        return Err(at.error("north", format!("must be horizontal (y = 0; y is up), got {}", show(north))));
    }
    let needs_sun = distribution.uses_sun() || raw.sun_illuminance.is_some_and(|e| e != 0.0);
    let position = sun_position(&at, raw, needs_sun)?;
    let sun = position.direction(north);
    let brightness = match (raw.zenith_luminance, raw.horizontal_illuminance) {
        (Some(_), Some(_)) => {
            return Err(at.error("zenith_luminance", "give `zenith_luminance` or `horizontal_illuminance`, not both"));
        }
        (Some(l), None) => {
            Brightness::Zenith(at.magnitude("zenith_luminance", at.positive("zenith_luminance", l)?, " cd/m²")?)
        }
        (None, e) => {
            let e = e.unwrap_or(DEFAULT_HORIZONTAL_ILLUMINANCE);
            Brightness::Horizontal(at.magnitude(
                "horizontal_illuminance",
                at.positive("horizontal_illuminance", e)?,
                " lx",
            )?)
        }
    };
    let ground = at.non_negative("ground_reflectance", raw.ground_reflectance.unwrap_or(DEFAULT_GROUND_REFLECTANCE))?;
    if ground > 1.0 {
        return Err(at.error("ground_reflectance", format!("must be at most 1, got {ground}")));
    }
    let sun_normal = match raw.sun_illuminance {
        None => 0.0,
        Some(e) => at.magnitude("sun_illuminance", at.non_negative("sun_illuminance", e)?, " lx")?,
    };
    let sun_horizontal = sun_normal * sun.y.max(0.0);
    let sky = Sky::new(distribution, sun, brightness, ground, sun_horizontal);
    unique_names(path, "window", windows.iter().map(|w| w.name.as_str()))?;
    let (mut luminaires, panes): (Vec<Luminaire>, Vec<Pane>) = windows
        .iter()
        .enumerate()
        .map(|(index, w)| window(&Context::item(path, "window", &w.name, index), w, placed[index], &sky))
        .collect::<Result<Vec<_>, _>>()?
        .into_iter()
        .unzip();
    let glass = BeamGlass::new(panes);
    if sun_normal > 0.0 && sun.y > 0.0 {
        let kind = LuminaireKind::Parallel { direction: -sun, illuminance: sun_normal, glass: glass.clone() };
        luminaires.push(Luminaire { name: "sun".to_string(), kind });
    }
    Ok((Some(sky), luminaires, glass))
}

/// Every parallel light among `luminaires` passes the windows' `glass` where it crosses them.
pub(super) fn glaze(luminaires: &mut [Luminaire], glass: &BeamGlass) {
    for luminaire in luminaires {
        if let LuminaireKind::Parallel { glass: own, .. } = &mut luminaire.kind {
            own.clone_from(glass);
        }
    }
}

/// The sun's position: `sun_altitude_deg` and `sun_azimuth_deg`, or the site and time;
/// none asked for when `needed` is false (a sky whose luminance does not depend on it, no
/// sun shining), the zenith standing in then.
fn sun_position(at: &Context, raw: &RawSky, needed: bool) -> Result<SunPosition, SceneError> {
    let site = [raw.latitude_deg.is_some(), raw.longitude_deg.is_some(), raw.date.is_some(), raw.time.is_some()];
    match (raw.sun_altitude_deg, raw.sun_azimuth_deg) {
        (None, None) if !needed && !site.contains(&true) => Ok(SunPosition { altitude_deg: 90.0, azimuth_deg: 0.0 }),
        (Some(h), Some(a)) if !site.contains(&true) => {
            let altitude_deg = at.finite("sun_altitude_deg", h)?;
            if altitude_deg.abs() > 90.0 {
                return Err(at.error("sun_altitude_deg", format!("must be from -90 to 90, got {altitude_deg}")));
            }
            Ok(SunPosition { altitude_deg, azimuth_deg: at.finite("sun_azimuth_deg", a)? })
        }
        (None, None) if !site.contains(&false) => site_time(at, raw).map(|s| s.sun()),
        _ => Err(at.error(
            "sun_altitude_deg",
            "give the sun as `sun_altitude_deg` and `sun_azimuth_deg`, or as `latitude_deg`, `longitude_deg`, \
             `date` and `time` (this sky's luminance or its `sun_illuminance` depends on where the sun is)",
        )),
    }
}

fn site_time(at: &Context, raw: &RawSky) -> Result<SiteTime, SceneError> {
    let latitude_deg = at.finite("latitude_deg", raw.latitude_deg.unwrap_or(0.0))?;
    if latitude_deg.abs() > 90.0 {
        return Err(at.error("latitude_deg", format!("must be from -90 to 90, got {latitude_deg}")));
    }
    let longitude_deg = at.finite("longitude_deg", raw.longitude_deg.unwrap_or(0.0))?;
    let date = raw.date.as_deref().unwrap_or("");
    let day_of_year =
        parse_date(date).ok_or_else(|| at.error("date", format!("must be a date \"YYYY-MM-DD\", got \"{date}\"")))?;
    let time = raw.time.as_deref().unwrap_or("");
    let hours = parse_time(time)
        .ok_or_else(|| at.error("time", format!("must be a local standard time \"HH:MM\", got \"{time}\"")))?;
    let timezone_h = at.finite("timezone_h", raw.timezone_h.unwrap_or((longitude_deg / 15.0).round()))?;
    Ok(SiteTime { latitude_deg, longitude_deg, day_of_year, hours, timezone_h })
}

fn parse_date(text: &str) -> Option<u32> {
    let mut parts = text.split('-');
    let (year, month, day) = (parts.next()?.parse().ok()?, parts.next()?.parse().ok()?, parts.next()?.parse().ok()?);
    parts.next().is_none().then_some(())?;
    day_of_year(year, month, day)
}

fn parse_time(text: &str) -> Option<f64> {
    let (h, m) = text.split_once(':')?;
    let (h, m): (u32, u32) = (h.parse().ok()?, m.parse().ok()?);
    (h < 24 && m < 60).then(|| h as f64 + m as f64 / 60.0)
}

/// The window's source (the sky and ground through it, times its maintenance factor) and
/// its pane for a beam.
fn window(at: &Context, w: &RawWindow, [origin, u, v]: [DVec3; 3], sky: &Sky) -> Result<(Luminaire, Pane), SceneError> {
    let polygon = ConvexPolygon::quad(origin, origin + u, origin + u + v, origin + v);
    let window = Opening { polygon, glazing: glazing(at, w)? };
    let maintenance = at.positive("maintenance_factor", w.maintenance_factor.unwrap_or(1.0))?;
    if maintenance > 1.0 {
        let message = format!("must be greater than 0 and at most 1 (the share of the light kept), got {maintenance}");
        return Err(at.error("maintenance_factor", message));
    }
    // The light through the opening, dirt included: the sky (and ground) seen through it
    // times the maintenance factor; the unobstructed sky outside (E_h) is unchanged.
    let kind = LuminaireKind::Window { window, sky: sky.scaled(maintenance) };
    let pane = Pane { name: w.name.clone(), opening: window, maintenance };
    Ok((Luminaire { name: w.name.clone(), kind }, pane))
}

/// `glass` (`"fresnel"` when `transmittance` is given), and for Fresnel panes
/// `transmittance`, `panes` (1 or 2, default 1) and `refractive_index` (default 1.52).
fn glazing(at: &Context, w: &RawWindow) -> Result<Option<Glazing>, SceneError> {
    let fresnel_keys = [
        ("transmittance", w.transmittance.is_some()),
        ("panes", w.panes.is_some()),
        ("refractive_index", w.refractive_index.is_some()),
    ];
    let given = fresnel_keys.into_iter().find(|(_, given)| *given).map(|(key, _)| key);
    match (w.glass, w.transmittance) {
        (Some(RawGlass::Cie171), _) => match given {
            Some(key) => Err(at.error(key, "does not apply to glass = \"cie171\", whose transmittance is CIE 171's")),
            None => Ok(Some(Glazing::Cie171)),
        },
        (_, Some(normal)) => fresnel(at, w, normal).map(|f| Some(Glazing::Fresnel(f))),
        (Some(RawGlass::Fresnel), None) => {
            Err(at.error("transmittance", "Fresnel panes need their normal transmittance"))
        }
        (None, None) => match given {
            Some(key) => Err(at.error(key, "applies only to a glazed window: give `transmittance`")),
            None => Ok(None),
        },
    }
}

/// Fresnel panes transmitting `normal` at normal incidence.
fn fresnel(at: &Context, w: &RawWindow, normal: f64) -> Result<Fresnel, SceneError> {
    let index = at.finite("refractive_index", w.refractive_index.unwrap_or(DEFAULT_REFRACTIVE_INDEX))?;
    if !(1.0..=4.0).contains(&index) || index == 1.0 {
        return Err(at.error("refractive_index", format!("must be greater than 1 and at most 4, got {index}")));
    }
    let panes = match w.panes.unwrap_or(1) {
        n @ (1 | 2) => n as u8,
        n => return Err(at.error("panes", format!("must be 1 or 2, got {n}"))),
    };
    let normal = at.positive("transmittance", normal)?;
    Fresnel::new(normal, index, panes).ok_or_else(|| {
        let most = Fresnel::lossless(index);
        at.error(
            "transmittance",
            format!("a pane of refractive index {index} transmits at most {most:.4}, got {normal}"),
        )
    })
}
