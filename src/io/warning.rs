//! [`Warning`]: what a solved field says is probably not meant (issue 18, item 4), one
//! variant a kind with the names and numbers its text states. `study::physics_warnings`
//! finds them; [`super::Solution`] keeps them typed, and they become text (`Display`) only
//! where they are printed or written to `/warnings`.

use std::fmt;

/// One physics warning of a solved case.
#[derive(Debug, Clone, PartialEq)]
pub enum Warning {
    /// Light lost on the back of one-sided surfaces, above 2 % of the flux emitted.
    BacksLost {
        /// Flux meeting backs, lm.
        lost: f64,
        /// Flux emitted, lm.
        emitted: f64,
        /// The (at most three) surfaces whose backs receive most, with the flux each
        /// receives, lm, most first.
        surfaces: Vec<(String, f64)>,
    },
    /// A point luminaire none of whose light reaches the front of a surface.
    LuminaireUnseen {
        /// The luminaire's name.
        luminaire: String,
        /// Share of its flux meeting backs, %.
        backs: f64,
    },
    /// A point luminaire more than half of whose flux meets the back of surfaces.
    LuminaireMostlyBacks {
        /// The luminaire's name.
        luminaire: String,
        /// Share of its flux meeting backs, %.
        backs: f64,
    },
    /// A probe whose sensor is not in the room.
    Probe {
        /// The probe's name.
        probe: String,
        /// What is wrong with it.
        fault: SensorFault,
    },
    /// A grid more than half of whose points are not in the room.
    Grid {
        /// The grid's name.
        grid: String,
        /// Points with a fault.
        faulty: usize,
        /// Points of the grid.
        points: usize,
        /// The first point's fault.
        first: SensorFault,
    },
    /// A probe in the near field of a patch it sees (`study`'s `near.rs`).
    NearPatch {
        /// The probe's name.
        probe: String,
        /// Its distance from the patch, m.
        distance: f64,
        /// The patch's surface.
        surface: String,
        /// The patch's diameter, m.
        diameter: f64,
        /// The share of the diameter below which a patch is near.
        near: f64,
    },
    /// More probes near a patch than are named one by one.
    MoreNearPatches {
        /// The probes not named.
        count: usize,
        /// The share of the diameter below which a patch is near.
        near: f64,
    },
    /// A negative escaped flux, explained and bounded by the kernel's columns.
    NegativeEscape(NegativeEscape),
    /// Light lost by the hierarchy's links themselves, whose columns carry less than the
    /// leaves' closures (`study`'s `openings.rs`).
    KernelLoss {
        /// Flux lost, lm.
        lost: f64,
        /// Flux emitted, lm.
        emitted: f64,
    },
    /// Light escaping through an opening small against the surfaces (`study`'s
    /// `openings.rs`).
    SmallOpening {
        /// Flux leaving the surfaces through it, lm.
        escaping: f64,
        /// Flux emitted, lm.
        emitted: f64,
        /// The opening's area, m².
        opening: f64,
        /// The surfaces' area, m².
        surfaces: f64,
        /// The (at most three) surfaces that see most of it, most first.
        seen_by: Vec<String>,
    },
    /// Points of a grid left out of its statistics: inside a solid or under a surface
    /// nearer than the grid's spacing (`readout::obstructed`).
    GridPointsLeftOut {
        /// The grid's name.
        grid: String,
        /// Points left out.
        left_out: usize,
        /// Points of the grid.
        points: usize,
        /// The grid's spacing, m.
        spacing: f64,
        /// The first few left out.
        named: Vec<LeftOut>,
    },
    /// A grid whose receiving side faces no luminaire, sun, opening or emitting surface.
    GridFacesAway {
        /// The grid's name.
        grid: String,
        /// Its normal (the receiving side).
        normal: [f64; 3],
    },
    /// A window none of whose light lands on a surface.
    WindowDark {
        /// The window's name.
        window: String,
    },
    /// Mirror surfaces whose light the kernel carries cell to cell, not by images
    /// (`study`'s `mirror_cells.rs`).
    MirrorsByCells {
        /// The mirror surfaces' names.
        surfaces: Vec<String>,
        /// Direction cells `K`.
        cells: usize,
        /// Why they have no images.
        cause: MirrorCause,
    },
}

/// Why a mirror's light is not carried by images (`docs/mirrors.md`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MirrorCause {
    /// The hierarchical kernel carries no images.
    Hierarchy,
    /// Parallel light or an opening lights the scene: only a point source has an image.
    NotPointLight,
    /// The mirror is not plane, emits, or faces another mirror.
    NotPlane,
}

/// A negative escaped flux of a closed scene: not light but discretization error, the
/// luminaires' part stated apart and the kernel's bounded by its columns' sent shares.
#[derive(Debug, Clone, PartialEq)]
pub struct NegativeEscape {
    /// The escaped flux, lm (negative).
    pub escaped: f64,
    /// Flux emitted, lm.
    pub emitted: f64,
    /// The luminaires' direct light landing on the patches beyond their flux, lm, when it
    /// is more than a rounding error.
    pub luminaires: Option<f64>,
    /// The smallest sent share of a column that sends light.
    pub low: f64,
    /// The largest.
    pub high: f64,
    /// The column whose deviation from 1 weighs most: its share and its place.
    pub worst: Option<(f64, String)>,
    /// The columns' excess over 1 weighted by the solved outgoing flux, lm.
    pub over: f64,
    /// Their deviation from 1 either way, weighted the same, lm.
    pub either: f64,
}

/// A grid point left out of the statistics: its cell and what stands over it.
#[derive(Debug, Clone, PartialEq)]
pub struct LeftOut {
    /// The cell `[u, v]` (as the CSV's columns `u`, `v`).
    pub cell: [usize; 2],
    /// The surface met first along the grid's normal.
    pub surface: String,
    /// The point is inside that surface's solid (the ray met its back).
    pub inside: bool,
    /// Distance to it along the normal, m.
    pub distance: f64,
}

impl fmt::Display for LeftOut {
    fn fmt(&self, f: &mut fmt::Formatter) -> fmt::Result {
        let [u, v] = self.cell;
        if self.inside {
            write!(f, "(u {u}, v {v}) inside \"{}\"", self.surface)
        } else {
            write!(f, "(u {u}, v {v}) {:.3} m under \"{}\"", self.distance, self.surface)
        }
    }
}

/// What is wrong with a sensor (a probe, a grid's point).
#[derive(Debug, Clone, PartialEq)]
pub enum SensorFault {
    /// Its normal points into the surface it lies on.
    IntoSurface {
        /// That surface's name.
        surface: String,
    },
    /// It sees mostly the backs of surfaces.
    Behind {
        /// Share of what it sees that is a back, %.
        backs: f64,
        /// The last back-facing surface it saw.
        surface: String,
    },
}

impl fmt::Display for SensorFault {
    fn fmt(&self, f: &mut fmt::Formatter) -> fmt::Result {
        match self {
            SensorFault::IntoSurface { surface } => {
                write!(f, "its normal points into the surface it lies on (\"{surface}\")")
            }
            SensorFault::Behind { backs, surface } => {
                write!(f, "{backs:.0} % of what it sees is the back of surfaces (\"{surface}\"): it lies behind one")
            }
        }
    }
}

impl fmt::Display for Warning {
    fn fmt(&self, f: &mut fmt::Formatter) -> fmt::Result {
        match self {
            Warning::BacksLost { lost, emitted, surfaces } => {
                let named: Vec<String> = surfaces.iter().map(|(name, lm)| format!("\"{name}\" {lm:.4} lm")).collect();
                write!(
                    f,
                    "about {lost:.4} lm ({:.1} % of the flux emitted) meets the back of one-sided surfaces, where it \
                     is lost: {}; a surface facing the wrong way (`inside`, the order of its vertices) or one meant \
                     to be two_sided",
                    100.0 * lost / emitted,
                    named.join(", ")
                )
            }
            Warning::LuminaireUnseen { luminaire, backs } => write!(
                f,
                "luminaire \"{luminaire}\": none of its light reaches the front of a surface ({backs:.0} % meets \
                 backs, the rest nothing): it lies inside or behind a surface"
            ),
            Warning::LuminaireMostlyBacks { luminaire, backs } => write!(
                f,
                "luminaire \"{luminaire}\": {backs:.0} % of its flux meets the back of surfaces (lost): it lies \
                 inside or behind a surface, or aims away from the room"
            ),
            Warning::Probe { probe, fault } => {
                write!(f, "probe \"{probe}\": {fault}; its readings are not of the room")
            }
            Warning::Grid { grid, faulty, points, first } => write!(
                f,
                "grid \"{grid}\": at {faulty} of its {points} points {first}; its illuminances are not of the room"
            ),
            Warning::NearPatch { probe, distance, surface, diameter, near } => write!(
                f,
                "probe \"{probe}\" lies {:.2} cm from a patch of \"{surface}\" {:.1} cm across, closer than {near} \
                 of its size: where it sees mostly the patch's nearest part, its reading is corrected by the light \
                 gathered at pieces of the patch (E_correction_lx; not for cylindrical kinds), which cannot mend a \
                 patch whose own mean is wrong (coarse leaves at a contact or in an umbra); compare with `ugo trace`",
                100.0 * distance,
                100.0 * diameter,
            ),
            Warning::MoreNearPatches { count, near } => {
                write!(f, "{count} more probes lie closer than {near} of a patch's size to a patch they see")
            }
            Warning::NegativeEscape(escape) => escape.fmt(f),
            Warning::KernelLoss { lost, emitted } => write!(
                f,
                "{lost:.4} lm ({:.1} % of the flux emitted) is lost by the hierarchy's links, not through an \
                 opening: light the solve delivers to no surface, so the surfaces read that much too dark between them. \
                 Their columns carry less light than the leaves' closures (a leaf's sending factor is held \
                 within a few link tolerances of 1, docs/hierarchy.md \"Sending factors held to the links' error\"); \
                 a smaller link_tolerance loses less",
                100.0 * lost / emitted
            ),
            Warning::SmallOpening { escaping, emitted, opening, surfaces, seen_by } => {
                let named: Vec<String> = seen_by.iter().map(|name| format!("\"{name}\"")).collect();
                write!(
                    f,
                    "{escaping:.4} lm ({:.1} % of the flux emitted) leaves the surfaces through an opening of about \
                     {opening:.4} m², {:.2} % of the {surfaces:.4} m² of surfaces: a nearly closed scene, so a \
                     missing wall or a gap between surfaces? The surfaces that see most of it: {}",
                    100.0 * escaping / emitted,
                    100.0 * opening / surfaces,
                    named.join(", ")
                )
            }
            Warning::GridPointsLeftOut { grid, left_out, points, spacing, named } => {
                let listed: Vec<String> = named.iter().map(ToString::to_string).collect();
                let more = left_out - named.len();
                write!(
                    f,
                    "grid \"{grid}\": {left_out} of its {points} points left out of E_avg, E_min, E_max and U0, inside \
                     a solid or under a surface nearer than the spacing {spacing:.3} m: {}{}",
                    listed.join(", "),
                    if more > 0 { format!(" and {more} more") } else { String::new() }
                )
            }
            Warning::GridFacesAway { grid, normal: [x, y, z] } => write!(
                f,
                "grid \"{grid}\": its receiving side (normal ({x}, {y}, {z})) faces away from every luminaire, sun, \
                 opening and emitting surface, so it reads only light reflected back at it; reverse `normal` (or \
                 swap `edge_u` and `edge_v`)"
            ),
            Warning::WindowDark { window } => write!(
                f,
                "window \"{window}\" lets in no light: none of it lands on a surface, so no surface sees its \
                 opening (it lies behind the room's surfaces or away from them); check its `origin` and edges"
            ),
            Warning::MirrorsByCells { surfaces, cells, cause } => {
                let named: Vec<String> = surfaces.iter().map(|name| format!("\"{name}\"")).collect();
                let degrees = (2.0 * std::f64::consts::PI / *cells as f64).sqrt().to_degrees();
                let (why, way_out) = match cause {
                    MirrorCause::Hierarchy => (
                        "the hierarchical kernel carries no images",
                        "--kernel uniform carries a plane mirror by images when every luminaire is a point source",
                    ),
                    MirrorCause::NotPointLight => (
                        "the scene has parallel light or an opening, whose light has no image",
                        "compare with ugo trace",
                    ),
                    MirrorCause::NotPlane => {
                        ("not plane, emitting, or facing another mirror", "compare with ugo trace")
                    }
                };
                write!(
                    f,
                    "mirror {} reflects cell to cell, not by images ({why}): its image is smeared over about \
                     {degrees:.0}° ({cells} direction cells), and what it lights may read several per cent off (the \
                     mirror room's floor by the mirror 4.9 % with the hierarchy, docs/mirrors.md); {way_out}",
                    named.join(", ")
                )
            }
        }
    }
}

impl fmt::Display for NegativeEscape {
    fn fmt(&self, f: &mut fmt::Formatter) -> fmt::Result {
        let NegativeEscape { escaped, emitted, luminaires, low, high, worst, over, either } = self;
        let share = |flux: f64| 100.0 * flux / emitted;
        write!(
            f,
            "the escaped flux is negative ({escaped:.4} lm, {:.3} % of the {emitted:.4} lm emitted): no light enters \
             from outside, so this is the discretization error, not a flux.",
            -share(*escaped)
        )?;
        if let Some(beyond) = luminaires {
            write!(
                f,
                " Of it, {:.4} lm is the luminaires' direct light on the patches exceeding their flux (the error of \
                 its integration over the patches); the rest, {:.4} lm, the kernel's.",
                -beyond,
                escaped + beyond
            )?;
        }
        write!(
            f,
            " The kernel's columns that send light, the share of the light each patch sends that the others \
             receive (π Σ_i A_i G_ij / (A_j μ)), lie between {low:.5} and {high:.5} where a closed scene has 1"
        )?;
        if let Some((largest, place)) = worst {
            write!(f, " (the largest part: {largest:.5} at {place})")?;
        }
        write!(
            f,
            "; weighted by the solved outgoing flux, their excess over 1 is {over:.4} lm (it bounds the kernel's \
             part) and their deviation either way {either:.4} lm, {:.3} % of the flux emitted: the energy balance, \
             and readings that depend on it, are uncertain by up to that share; a smaller patch_size lowers it",
            share(*either)
        )
    }
}
