//! Daylight quantities at probes and grid points (`docs/daylight.md`): the sky component
//! SC (the sky seen directly through the openings), the externally reflected component
//! ERC (the ground seen through them), the internally reflected component IRC (all the
//! light from the room's surfaces) and the daylight factor `DF = E / E_h`, every one in %
//! of the unobstructed sky's horizontal illuminance `E_h` (the sun excluded).
//!
//! SC and ERC come from the openings piece by piece exactly as the source term does
//! (`openings.rs`); `E` is the probe's or grid
//! point's illuminance from the solved field (`probe.rs`), and `IRC = E − E_direct`, the
//! direct light of every source (openings, sun, luminaires) taken away. Under a sky
//! without sun or luminaires `DF = SC + ERC + IRC`. `E / E_h` is the daylight factor only
//! under a sky whose luminance does not depend on the sun, with no sun shining
//! (`Sky::gives_daylight_factor`); otherwise it is the daylight ratio, and is labelled so.

use crate::model::Model;
use crate::readout::cylindrical::openings;
use crate::readout::grid::GridReading;
use crate::readout::openings::sky_and_ground;
use crate::readout::probe::ProbeReading;
use crate::scene::ProbeKind;
use crate::sky::Sky;
use glam::DVec3;

/// The daylight at one point, in % of `E_h`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Daylight {
    /// Sky component SC: the sky seen directly through the openings, %.
    pub sky_component: f64,
    /// Externally reflected component ERC: the ground seen through the openings, %.
    pub externally_reflected: f64,
    /// Internally reflected component IRC: the light from the room's surfaces, %.
    pub internally_reflected: f64,
    /// Daylight factor `DF = E / E_h`, %.
    pub daylight_factor: f64,
}

/// Statistics of the daylight factor over a grid, %.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DaylightStats {
    /// Average daylight factor, %.
    pub average: f64,
    /// Smallest daylight factor, %.
    pub min: f64,
    /// Largest daylight factor, %.
    pub max: f64,
    /// `DF_min / DF_avg` (0 when the average is 0).
    pub uniformity: f64,
}

/// The daylight at `p` facing `n` whose illuminance is `illuminance` lx, `direct` lx of it
/// directly from the sources, under `sky`.
pub fn daylight_at(model: &Model, sky: &Sky, p: DVec3, n: DVec3, illuminance: f64, direct: f64) -> Daylight {
    components(sky, sky_and_ground(model, p, n), illuminance, direct)
}

/// The daylight in % of `E_h` of a reading of `illuminance` lx, `direct` lx of it directly
/// from the sources, `(s, g)` lx of that from the sky and the ground through the openings.
fn components(sky: &Sky, (s, g): (f64, f64), illuminance: f64, direct: f64) -> Daylight {
    let percent = 100.0 / sky.horizontal_illuminance;
    Daylight {
        sky_component: s * percent,
        externally_reflected: g * percent,
        internally_reflected: (illuminance - direct) * percent,
        daylight_factor: illuminance * percent,
    }
}

/// The daylight at every probe; a cylindrical or semi-cylindrical probe's SC and ERC are
/// the openings' light on its curved side (`cylindrical::openings`), as its reading.
pub fn probe_daylight(model: &Model, sky: &Sky, probes: &[ProbeReading]) -> Vec<Daylight> {
    probes
        .iter()
        .map(|r| {
            let (p, n) = (r.position, r.normal);
            let (s, g) = match r.kind {
                ProbeKind::Cylindrical => openings(model, p, n, None),
                ProbeKind::SemiCylindrical { axis } => openings(model, p, axis, Some(n)),
                ProbeKind::Point | ProbeKind::LuminanceMeter { .. } => sky_and_ground(model, p, n),
            };
            components(sky, (s, g), r.illuminance, r.direct)
        })
        .collect()
}

/// The daylight at every point of a grid.
pub fn grid_daylight(model: &Model, sky: &Sky, grid: &GridReading) -> Vec<Daylight> {
    let n = grid.grid.normal;
    let at = |(p, (e, direct)): (&DVec3, (&f64, &f64))| daylight_at(model, sky, *p, n, *e, *direct);
    grid.points.iter().zip(grid.illuminance.iter().zip(&grid.direct)).map(at).collect()
}

/// `DF_avg`, `DF_min`, `DF_max` and the uniformity `DF_min / DF_avg` of equal cells, over
/// the points of `grid` that count (as its illuminance's statistics).
pub fn stats(daylight_factor: &[f64], grid: &GridReading) -> DaylightStats {
    let s = grid.stats_of(daylight_factor);
    DaylightStats { average: s.average, min: s.min, max: s.max, uniformity: s.u0 }
}

/// The daylight readouts of a solve under a `[sky]`.
#[derive(Debug, Clone, PartialEq)]
pub struct DaylightReadings {
    /// `E_h`, lx: the unobstructed sky's horizontal illuminance every quantity is a share of.
    pub horizontal_illuminance: f64,
    /// `E / E_h` is the daylight factor (an overcast or uniform sky, no sun), not the
    /// daylight ratio.
    pub factor: bool,
    /// One per probe.
    pub probes: Vec<Daylight>,
    /// The daylight at every point of every grid, grid by grid.
    pub grids: Vec<Vec<Daylight>>,
}

impl DaylightReadings {
    /// What `E / E_h` is: `"daylight factor"` or `"daylight ratio"`.
    pub fn quantity(&self) -> &'static str {
        if self.factor { "daylight factor" } else { "daylight ratio" }
    }

    /// The daylight factor (or ratio), %, at every point of grid `g`.
    pub fn grid_factor(&self, g: usize) -> Vec<f64> {
        self.grids[g].iter().map(|d| d.daylight_factor).collect()
    }

    /// Its symbol in tables and plans: `"DF"` or `"DR"`.
    pub fn symbol(&self) -> &'static str {
        if self.factor { "DF" } else { "DR" }
    }
}

/// The daylight at the probes and grids already read, under `sky`.
pub fn read_daylight(model: &Model, sky: &Sky, probes: &[ProbeReading], grids: &[GridReading]) -> DaylightReadings {
    DaylightReadings {
        horizontal_illuminance: sky.horizontal_illuminance,
        factor: sky.gives_daylight_factor(),
        probes: probe_daylight(model, sky, probes),
        grids: grids.iter().map(|g| grid_daylight(model, sky, g)).collect(),
    }
}
