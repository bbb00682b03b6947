//! The sky as a boundary condition of the global illumination equation (`docs/design.md` §1,
//! `docs/daylight.md`): luminance arriving from a direction `l` that leaves the scene is the
//! sky's `L_sky(l)` above the horizon and the ground's below it.
//!
//! Owns the CIE sky luminance distributions (`standard.rs`: the 15 standard general skies
//! of ISO 15469/CIE S 011 and the traditional overcast sky), the sun's position
//! (`sun.rs`), the normalisation by the zenith luminance or by the unobstructed horizontal
//! illuminance (`integrate.rs`), and the light a receiving point gets through an opening
//! (`window.rs`, glazed or not: `glazing.rs`, the models in `glazing_*.rs`): sky and ground
//! seen through the opening's polygon, piece by piece, each piece's exact projected solid
//! angle times the luminance towards it, shadows included, and a rough look at the whole
//! opening at once for choosing where leaves split (`glimpse.rs`); and the share of a parallel beam
//! (the sun) the openings' glass lets through (`beam_glass.rs`).
//! The sky enters the system exactly like a luminaire's direct light (`crate::luminaire`,
//! `Light::Window`); nothing here knows about patches' cells or materials.
//!
//! Frames: y is up; `north` is a unit horizontal world vector and east is `north × up`.
//! The ground is a uniform Lambertian plane of reflectance `ρ_g` below the horizon:
//! `L_g = ρ_g (E_h + E_sun,h)/π`, lit by the unobstructed sky and the sun.

mod beam_glass;
mod glazing;
mod glazing_cie171;
mod glazing_fresnel;
pub mod glimpse;
mod integrate;
mod standard;
mod sun;
mod window;

pub use beam_glass::{BeamGlass, Pane};
pub use glazing::Glazing;
pub use glazing_cie171::COEFFICIENTS as CIE171_GLASS;
pub use glazing_fresnel::Fresnel;
pub use integrate::{gauss_legendre, hemisphere};
pub use standard::{Distribution, GENERAL, Parameters, gradation, indicatrix};
pub use sun::{SiteTime, SunPosition, day_of_year, declination_and_equation_of_time};
pub use window::{Component, Cuts, ETA, MAX_DEPTH, Opening, READING, SHADOW_SHARE, through_window, unshadowed};

use glam::DVec3;
use std::f64::consts::PI;

/// A sky of known luminance: distribution, sun, scale and ground.
#[derive(Debug, Clone, PartialEq)]
pub struct Sky {
    /// The relative luminance distribution (a CIE sky).
    pub distribution: Distribution,
    /// Unit world direction towards the sun (it may be below the horizon).
    pub sun: DVec3,
    /// Luminance at the zenith, cd/m².
    pub zenith_luminance: f64,
    /// Horizontal illuminance of the unobstructed sky alone (no sun), lx.
    pub horizontal_illuminance: f64,
    /// Reflectance of the ground below the horizon.
    pub ground_reflectance: f64,
    /// Illuminance of the direct sun on a horizontal plane, lx (0 without a sun).
    pub sun_horizontal: f64,
}

/// How bright a sky is given.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Brightness {
    /// The zenith luminance, cd/m².
    Zenith(f64),
    /// The horizontal illuminance of the unobstructed sky, lx.
    Horizontal(f64),
}

impl Sky {
    /// `E / E_h` is the daylight factor proper: the sky's luminance does not depend on the
    /// sun (the overcast and uniform skies) and no sun shines. Otherwise it is the daylight
    /// ratio, which depends on the hour and the orientation.
    pub fn gives_daylight_factor(&self) -> bool {
        !self.distribution.uses_sun() && self.sun_horizontal == 0.0
    }

    /// The sky of `distribution` with the sun towards `sun`, scaled by `brightness`; the
    /// ground of reflectance `ground_reflectance` is also lit by `sun_horizontal` lx.
    pub fn new(
        distribution: Distribution,
        sun: DVec3,
        brightness: Brightness,
        ground_reflectance: f64,
        sun_horizontal: f64,
    ) -> Sky {
        let ratio = relative_horizontal_illuminance(distribution, sun);
        let (zenith_luminance, horizontal_illuminance) = match brightness {
            Brightness::Zenith(l) => (l, l * ratio),
            Brightness::Horizontal(e) => (e / ratio, e),
        };
        Sky { distribution, sun, zenith_luminance, horizontal_illuminance, ground_reflectance, sun_horizontal }
    }

    /// The luminance of the sky towards the unit world direction `l` (y up), cd/m²; the
    /// ground's at and below the horizon.
    pub fn luminance(&self, l: DVec3) -> f64 {
        match l.y > 0.0 {
            true => self.sky_luminance(l),
            false => self.ground_luminance(),
        }
    }

    /// The sky's luminance towards `l`, its elevation taken as at least 0, cd/m².
    pub fn sky_luminance(&self, l: DVec3) -> f64 {
        self.zenith_luminance * self.distribution.relative(l, self.sun)
    }

    /// The same sky (and sun on the ground) `factor` times as bright.
    pub fn scaled(&self, factor: f64) -> Sky {
        Sky {
            zenith_luminance: self.zenith_luminance * factor,
            horizontal_illuminance: self.horizontal_illuminance * factor,
            sun_horizontal: self.sun_horizontal * factor,
            ..self.clone()
        }
    }

    /// `L_g = ρ_g (E_h + E_sun,h)/π`, cd/m².
    pub fn ground_luminance(&self) -> f64 {
        self.ground_reflectance * (self.horizontal_illuminance + self.sun_horizontal) / PI
    }
}

/// `E_h / L_z` of `distribution` with the sun towards `sun`, sr.
pub fn relative_horizontal_illuminance(distribution: Distribution, sun: DVec3) -> f64 {
    hemisphere(|u, azimuth| {
        let s = (1.0 - u * u).max(0.0).sqrt();
        distribution.relative(DVec3::new(s * azimuth.cos(), u, s * azimuth.sin()), sun)
    })
}
