//! Photons from the sky, the ground and the sun through the `[[window]]` openings, for light
//! tracing (`docs/design.md` §4; the sky is the boundary condition of §1, `docs/daylight.md`).
//!
//! Each side of each opening is a photon source. The sky's: a uniform point `x` of the
//! opening (area `A`), a cosine-distributed direction `l` towards that side; if the ray from
//! `x` along `l` leaves the scene (nothing outside blocks it) the photon enters along `−l`
//! carrying `L(l) τ(θ)` (`Sky::luminance`, the window's sky already times its maintenance
//! factor, `τ` its glazing at the incidence `θ`). A side's flux
//! `Φ_s = A ∫ L τ cos θ dω` is tabulated by a 64 × 64 midpoint rule in the cosine-weighted
//! square, times the share of 64 test rays that leave the scene (at least 1 %), so the inner
//! side of a window in a closed room takes almost none; the photons' weights
//! `π L τ A / Φ_s` make the estimate unbiased whatever the table's error. The sun (every
//! parallel light): a uniform point of each opening it meets, its beam `E_n` along its
//! direction `d` over the opening's projected area `A |cos θ|`, weight `T(x)/τ(θ)` with `T`
//! the share the glass it crosses lets through (`sky::BeamGlass`) and 0 when the ray towards
//! the sun is blocked (obstructions outside) or meets the room (the sun on the inner side).
//!
//! As the deterministic source term does, every opening is a source of its own: a room
//! that sees one opening through another (two glazed openings in a row) counts both, where
//! the backward tracer sees the sky once through the two panes.

use super::emitters::Departure;
use super::openings::pick;
use crate::geometry::{Frame, cosine_direction};
use crate::luminaire::{Light, Source};
use crate::sky::{BeamGlass, Opening, Sky};
use crate::visibility::{NO_FACE, Visibility};
use glam::DVec3;
use std::f64::consts::PI;

/// Midpoints per axis of the cosine-weighted square tabulating a side's flux.
const TABLE: usize = 64;
/// Test rays per side for the share that leaves the scene.
const TEST_RAYS: usize = 64;
/// The least share of a side's tabulated flux kept, so that no side is never sampled.
const LEAST_OPEN: f64 = 0.01;

/// The daylight's photon sources.
#[derive(Debug, Clone, Default)]
pub struct DaylightPhotons {
    sources: Vec<Entry>,
    /// Tabulated flux of each source, lm.
    flux: Vec<f64>,
    /// Each source's share of the total.
    chance: Vec<f64>,
}

/// One side of an opening under the sky, or one opening under a beam.
#[derive(Debug, Clone)]
enum Entry {
    Sky { opening: Opening, sky: Sky, frame: Frame },
    Beam { opening: Opening, direction: DVec3, illuminance: f64, glass: BeamGlass },
}

impl DaylightPhotons {
    /// The openings among `sources`, each side under its sky, and every parallel light
    /// through each opening (none without openings: parallel light then enters across the
    /// scene, `luminaires.rs`).
    pub fn of(sources: &[Source], visibility: &Visibility) -> DaylightPhotons {
        let mut out = DaylightPhotons::default();
        for (opening, sky) in sources.iter().filter_map(|s| match &s.light {
            Light::Window { window, sky } => Some((window, sky)),
            _ => None,
        }) {
            for normal in [opening.polygon.normal(), -opening.polygon.normal()] {
                let frame = Frame::around(normal);
                let flux = sky_flux(opening, sky, &frame) * open_share(opening, &frame, visibility).max(LEAST_OPEN);
                out.push(Entry::Sky { opening: *opening, sky: sky.clone(), frame }, flux);
            }
            for source in sources {
                if let Light::Parallel { direction, illuminance, glass } = &source.light {
                    let cos = direction.dot(opening.polygon.normal()).abs();
                    let tau = opening.glazing.map_or(1.0, |g| g.transmittance(cos));
                    let entry = Entry::Beam {
                        opening: *opening,
                        direction: *direction,
                        illuminance: *illuminance,
                        glass: glass.clone(),
                    };
                    out.push(entry, illuminance * opening.polygon.area() * cos * tau);
                }
            }
        }
        let total = out.flux();
        out.chance = out.flux.iter().map(|f| f / total).collect();
        out
    }

    fn push(&mut self, entry: Entry, flux: f64) {
        if flux > 0.0 && flux.is_finite() {
            self.sources.push(entry);
            self.flux.push(flux);
        }
    }

    /// True when nothing comes in through openings.
    pub fn is_empty(&self) -> bool {
        self.sources.is_empty()
    }

    /// Total tabulated flux, lm.
    pub fn flux(&self) -> f64 {
        self.flux.iter().sum()
    }

    /// A photon: `u[0]` picks a source by flux, the rest place and aim it; with its weight
    /// (0 when the sky or the sun is blocked there).
    pub fn emit(&self, visibility: &Visibility, u: [f64; 5]) -> Option<(Departure, f64)> {
        let (i, v) = pick(&self.chance, u[0])?;
        match &self.sources[i] {
            Entry::Sky { opening, sky, frame } => {
                let x = opening.polygon.point_at(v, u[1], u[2]);
                let l = frame.world(cosine_direction(u[3], u[4]));
                let open = visibility.escapes(x, l, NO_FACE);
                let cos = l.dot(opening.polygon.normal()).abs();
                let tau = opening.glazing.map_or(1.0, |g| g.transmittance(cos));
                let weight =
                    if open { PI * sky.luminance(l) * tau * opening.polygon.area() / self.flux[i] } else { 0.0 };
                Some((Departure { origin: x, direction: -l, face: NO_FACE }, weight))
            }
            Entry::Beam { opening, direction, illuminance, glass } => {
                let x = opening.polygon.point_at(v, u[1], u[2]);
                let open = visibility.escapes(x, -*direction, NO_FACE);
                // just inside the opening, so that the opening's own glass counts
                let inside = x + *direction * (1e-9 * opening.polygon.diameter());
                let cos = direction.dot(opening.polygon.normal()).abs();
                let flux = illuminance * opening.polygon.area() * cos;
                let weight = if open { flux * glass.share(inside, -*direction) / self.flux[i] } else { 0.0 };
                Some((Departure { origin: x, direction: *direction, face: NO_FACE }, weight))
            }
        }
    }
}

/// `A ∫ L(l) τ(θ) cos θ dω` over the hemisphere of `frame.normal`, by the midpoint rule in
/// the cosine-weighted square (`π` times the mean), lm.
fn sky_flux(opening: &Opening, sky: &Sky, frame: &Frame) -> f64 {
    let mut sum = 0.0;
    for a in 0..TABLE {
        for b in 0..TABLE {
            let l = frame.world(cosine_direction((a as f64 + 0.5) / TABLE as f64, (b as f64 + 0.5) / TABLE as f64));
            let tau = opening.glazing.map_or(1.0, |g| g.transmittance(l.dot(frame.normal)));
            sum += sky.luminance(l) * tau;
        }
    }
    PI * opening.polygon.area() * sum / (TABLE * TABLE) as f64
}

/// The share of [`TEST_RAYS`] rays from the opening's points towards `frame.normal`'s side
/// that leave the scene.
fn open_share(opening: &Opening, frame: &Frame, visibility: &Visibility) -> f64 {
    let side = (TEST_RAYS as f64).sqrt() as usize;
    let mut open = 0;
    for k in 0..TEST_RAYS {
        let (s, t) = (((k % side) as f64 + 0.5) / side as f64, ((k / side) as f64 + 0.5) / side as f64);
        let x = opening.polygon.point_at(s, t, 0.5);
        let l = frame.world(cosine_direction(t, s));
        open += usize::from(visibility.escapes(x, l, NO_FACE));
    }
    open as f64 / TEST_RAYS as f64
}
