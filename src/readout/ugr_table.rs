//! The tabular UGR of CIE 190:2010 (`docs/photometry.md`, "The UGR table"): the UGR of
//! CIE 117 (`docs/design.md` (5.7), [`unified_glare_rating`]) of one luminaire in the 19
//! standard rooms, viewed crosswise and endwise, under the five reflectance combinations,
//! at the luminaire's own flux; the table of the reference flux is that less the summand
//! `8 log10(Φ/Φ_ref)`. Each cell counts every luminaire of the room's array
//! (`standard_room.rs`) within the extent of Guth's table (`T/R ≤ 3`), seen by
//! [`glare_source`] exactly as an `[[observer]]` sees a luminaire, and takes the
//! background `L_b = E_WID/π` from the mean indirect illuminance of the walls in the
//! three-surface room (`cavity.rs`, `docs/design.md` (5.8)).

use super::cavity::{Reflectances, Transfer};
use super::standard_room::{StandardRoom, Viewing};
use super::ugr::{GlareSource, glare_source, unified_glare_rating};
use crate::luminaire::Source;
use crate::photometry::Distribution;
use glam::DVec3;
use std::f64::consts::PI;

/// The standard rooms `[X, Y]` in multiples of `H`, `X` across the line of sight.
pub const ROOMS: [[f64; 2]; 19] = [
    [2.0, 2.0],
    [2.0, 3.0],
    [2.0, 4.0],
    [2.0, 6.0],
    [2.0, 8.0],
    [2.0, 12.0],
    [4.0, 2.0],
    [4.0, 3.0],
    [4.0, 4.0],
    [4.0, 6.0],
    [4.0, 8.0],
    [4.0, 12.0],
    [8.0, 4.0],
    [8.0, 6.0],
    [8.0, 8.0],
    [8.0, 12.0],
    [12.0, 4.0],
    [12.0, 6.0],
    [12.0, 8.0],
];

/// The reflectance combinations, ceiling / walls / reference plane.
pub const REFLECTANCES: [Reflectances; 5] = [
    Reflectances { ceiling: 0.7, walls: 0.5, floor: 0.2 },
    Reflectances { ceiling: 0.7, walls: 0.3, floor: 0.2 },
    Reflectances { ceiling: 0.5, walls: 0.5, floor: 0.2 },
    Reflectances { ceiling: 0.5, walls: 0.3, floor: 0.2 },
    Reflectances { ceiling: 0.3, walls: 0.3, floor: 0.2 },
];

/// `H`, the luminaires' height above the eye, m: the UGR does not depend on it (`L² ω`
/// and `L_b` both scale as `1/H²`), the solid angles do.
pub const HEIGHT: f64 = 2.0;

/// The flux the reference table is given for, lm (per 1000 lm of lamp flux).
pub const REFERENCE_FLUX: f64 = 1000.0;

/// The spacing-to-height ratio of the catalogue tables.
pub const CATALOGUE_SPACING: f64 = 0.25;

/// The largest `T/R` (across the line of sight over along it) counted: Guth's table ends there.
pub const MOST_ACROSS: f64 = 3.0;

/// One cell of the table, at the luminaire's flux.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cell {
    /// The room, multiples of `H`.
    pub room: [f64; 2],
    /// How it is viewed.
    pub viewing: Viewing,
    /// Under which reflectances.
    pub reflectances: Reflectances,
    /// The UGR.
    pub ugr: f64,
    /// `L_b`, cd/m².
    pub background: f64,
    /// The room index `k`.
    pub room_index: f64,
}

/// A luminaire's UGR table.
#[derive(Debug, Clone, PartialEq)]
pub struct UgrTable {
    /// Room by room (the order of [`ROOMS`]), crosswise then endwise, then the reflectances.
    pub cells: Vec<Cell>,
    /// The flux the cells are given at, lm (the luminaire's lamp flux).
    pub flux: f64,
    /// The spacing-to-height ratio of the arrays.
    pub spacing: f64,
    /// The smallest and largest solid angle of a luminaire counted, sr.
    pub solid_angles: [f64; 2],
}

impl UgrTable {
    /// `8 log10(Φ/Φ_ref)`: what the table of [`REFERENCE_FLUX`] lacks.
    pub fn summand(&self) -> f64 {
        8.0 * (self.flux / REFERENCE_FLUX).log10()
    }
}

/// The table of `distribution`, whose lamps give `flux` lm, at the spacing-to-height `ratio`.
pub fn ugr_table(distribution: &Distribution, flux: f64, ratio: f64) -> UgrTable {
    let mut cells = Vec::with_capacity(ROOMS.len() * 10);
    let mut solid_angles = [f64::INFINITY, 0.0];
    for room in ROOMS {
        for viewing in Viewing::BOTH {
            let placed = StandardRoom::new(room, HEIGHT, ratio, viewing);
            let source = placed.luminaire(distribution);
            let seen = counted(&placed, &source);
            for s in &seen {
                solid_angles = [solid_angles[0].min(s.solid_angle), solid_angles[1].max(s.solid_angle)];
            }
            let shares = placed.shares(&source);
            let luminaires = (placed.counts[0] * placed.counts[1]) as f64;
            for reflectances in REFLECTANCES {
                let Transfer { floor, walls, ceiling } = placed.cavity.transfer(reflectances);
                let reflected = shares.floor * floor + shares.walls * walls + shares.ceiling * ceiling;
                let background = luminaires * reflected / placed.cavity.wall_area() / PI;
                let ugr = unified_glare_rating(&seen, background);
                let room_index = placed.cavity.room_index();
                cells.push(Cell { room, viewing, reflectances, ugr, background, room_index });
            }
        }
    }
    UgrTable { cells, flux, spacing: ratio, solid_angles }
}

/// The luminaires of the array the eye counts, seen from it.
fn counted(placed: &StandardRoom, source: &Source) -> Vec<GlareSource> {
    placed
        .positions()
        .filter(|p| p.x.abs() <= MOST_ACROSS * p.z)
        .filter_map(|p| glare_source(source, -p, DVec3::Z))
        .collect()
}
