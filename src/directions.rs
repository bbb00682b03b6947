//! Direction sets `{C_k}`: partitions of the hemisphere (or sphere) of directions into
//! cells (`docs/design.md` §2).
//!
//! Every set is made of rings between two polar angles, each ring cut into equal azimuth
//! sectors starting at `φ = 0`; the upper hemisphere comes first, from the pole down. Each
//! cell has a representative direction in the patch's local frame `(t, b, N)` (its centre
//! in `cosθ` and `φ`), its solid angle `ω_k` and projected solid angle
//! `μ_k = ∫_{C_k} |cosθ| dω`. Lookup of a direction is a binary search over the rings and
//! one division for the sector.
//!
//! * `hemisphere(K)`: equal solid angle `2π/K` (a polar cap and rings whose cell counts
//!   keep cells near square, after Leopardi's recursive zonal partition, ETNA 25 (2006)).
//! * `sphere(K)`: `hemisphere(K/2)` and its mirror image below the surface (for two-sided
//!   transmitting surfaces): `Σ ω = 4π`.
//! * `klems`: the 145-cell Klems full basis (polar edges 0, 5, 15, …, 75, 90°; cells of
//!   about equal *projected* solid angle), `tregenza`: the 145-patch Tregenza sky.
//! * `K = 1` is classic radiosity: one cell, the whole hemisphere.

use glam::DVec3;
use std::f64::consts::{FRAC_PI_2, PI, TAU};

/// One direction cell.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cell {
    /// Representative unit direction, local frame (z along the normal).
    pub direction: DVec3,
    /// Solid angle, sr.
    pub solid_angle: f64,
    /// Projected solid angle `∫ |cosθ| dω`, sr.
    pub projected: f64,
}

/// Polar band `cos_bottom < cosθ ≤ cos_top` of the upper hemisphere, `count` sectors.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Ring {
    cos_top: f64,
    cos_bottom: f64,
    count: usize,
    first: usize,
}

/// A partition of the hemisphere (or of the sphere) into `K` cells.
#[derive(Debug, Clone, PartialEq)]
pub struct DirectionSet {
    name: String,
    rings: Vec<Ring>,
    /// The lower hemisphere is the mirror image of the upper one, cells `K/2..K`.
    sphere: bool,
    cells: Vec<Cell>,
}

impl DirectionSet {
    /// `K = 1`: the whole hemisphere, radiosity.
    pub fn single() -> DirectionSet {
        DirectionSet::from_rings("1".into(), &[(1.0, 0.0, 1)], false)
    }

    /// `K` cells of equal solid angle `2π/K` over the hemisphere.
    pub fn hemisphere(k: usize) -> DirectionSet {
        assert!(k >= 1, "a direction set has at least one cell");
        DirectionSet::from_rings(k.to_string(), &equal_area_rings(k), false)
    }

    /// `K` cells (even) of equal solid angle `4π/K` over the whole sphere.
    pub fn sphere(k: usize) -> DirectionSet {
        assert!(k >= 2 && k.is_multiple_of(2), "a sphere set has an even number of cells");
        DirectionSet::from_rings(format!("sphere {k}"), &equal_area_rings(k / 2), true)
    }

    /// The 145-cell Klems full basis.
    pub fn klems() -> DirectionSet {
        let edges = [0.0, 5.0, 15.0, 25.0, 35.0, 45.0, 55.0, 65.0, 75.0, 90.0];
        DirectionSet::from_polar_edges("klems", &edges, &[1, 8, 16, 20, 24, 24, 24, 16, 12])
    }

    /// The 145-patch Tregenza sky subdivision (bands of 12° altitude, 6° zenith cap).
    pub fn tregenza() -> DirectionSet {
        let edges = [0.0, 6.0, 18.0, 30.0, 42.0, 54.0, 66.0, 78.0, 90.0];
        DirectionSet::from_polar_edges("tregenza", &edges, &[1, 6, 12, 18, 24, 24, 30, 30])
    }

    fn from_polar_edges(name: &str, degrees: &[f64], counts: &[usize]) -> DirectionSet {
        let rings: Vec<(f64, f64, usize)> = degrees
            .windows(2)
            .zip(counts)
            .map(|(w, &n)| (w[0].to_radians().cos(), w[1].to_radians().cos(), n))
            .collect();
        DirectionSet::from_rings(name.into(), &rings, false)
    }

    fn from_rings(name: String, spec: &[(f64, f64, usize)], sphere: bool) -> DirectionSet {
        let mut rings = Vec::with_capacity(spec.len());
        let mut cells = Vec::new();
        for &(cos_top, cos_bottom, count) in spec {
            rings.push(Ring { cos_top, cos_bottom, count, first: cells.len() });
            let cos_mid = 0.5 * (cos_top + cos_bottom);
            let sin_mid = (1.0 - cos_mid * cos_mid).sqrt();
            for s in 0..count {
                let phi = TAU * (s as f64 + 0.5) / count as f64;
                let direction = if cos_top == 1.0 && count == 1 {
                    DVec3::Z
                } else {
                    DVec3::new(sin_mid * phi.cos(), sin_mid * phi.sin(), cos_mid)
                };
                cells.push(Cell {
                    direction,
                    solid_angle: TAU * (cos_top - cos_bottom) / count as f64,
                    projected: PI * (cos_top * cos_top - cos_bottom * cos_bottom) / count as f64,
                });
            }
        }
        if sphere {
            let mirrored: Vec<Cell> =
                cells.iter().map(|c| Cell { direction: c.direction * DVec3::new(1.0, 1.0, -1.0), ..*c }).collect();
            cells.extend(mirrored);
        }
        DirectionSet { name, rings, sphere, cells }
    }

    /// The set's name: its [`Scheme`]'s (or `"sphere K"`).
    pub fn name(&self) -> &str {
        &self.name
    }

    /// Number of cells, `K`.
    pub fn len(&self) -> usize {
        self.cells.len()
    }

    /// True when the set has no cells.
    pub fn is_empty(&self) -> bool {
        self.cells.is_empty()
    }

    /// The cells, in index order.
    pub fn cells(&self) -> &[Cell] {
        &self.cells
    }

    /// True when the set covers the whole sphere.
    pub fn is_sphere(&self) -> bool {
        self.sphere
    }

    /// The cell holding a local-frame unit direction. Directions below the surface map
    /// to the mirror cells of a sphere set, and to the cell of their mirror image above
    /// the surface otherwise.
    #[inline]
    pub fn lookup(&self, local: DVec3) -> usize {
        let (z, offset) =
            if local.z < 0.0 { (-local.z, if self.sphere { self.cells.len() / 2 } else { 0 }) } else { (local.z, 0) };
        let r = self.rings.partition_point(|ring| ring.cos_bottom >= z).min(self.rings.len() - 1);
        let ring = &self.rings[r];
        if ring.count == 1 {
            return offset + ring.first;
        }
        let mut phi = local.y.atan2(local.x);
        if phi < 0.0 {
            phi += TAU;
        }
        let sector = ((phi / TAU * ring.count as f64) as usize).min(ring.count - 1);
        offset + ring.first + sector
    }

    /// Bounds of cell `k` in the upper hemisphere: `(cos_bottom, cos_top, φ_start, φ_end)`.
    pub fn bounds(&self, k: usize) -> (f64, f64, f64, f64) {
        let k = k % (self.cells.len() / if self.sphere { 2 } else { 1 });
        let ring = self.rings.iter().rev().find(|r| r.first <= k).expect("cell in a ring");
        let width = TAU / ring.count as f64;
        let s = (k - ring.first) as f64;
        (ring.cos_bottom, ring.cos_top, s * width, (s + 1.0) * width)
    }
}

/// Rings `(cos_top, cos_bottom, count)` of an equal-solid-angle partition into `k` cells.
fn equal_area_rings(k: usize) -> Vec<(f64, f64, usize)> {
    if k == 1 {
        return vec![(1.0, 0.0, 1)];
    }
    let cap = (1.0 - 1.0 / k as f64).acos();
    let size = (TAU / k as f64).sqrt();
    let bands = (((FRAC_PI_2 - cap) / size).round() as usize).max(1);
    let height = (FRAC_PI_2 - cap) / bands as f64;
    let mut counts = vec![1usize];
    let (mut carry, mut placed) = (0.0, 1usize);
    for j in 1..=bands {
        let (top, bottom) = ((cap + (j - 1) as f64 * height).cos(), (cap + j as f64 * height).cos());
        let ideal = (top - bottom) * k as f64 + carry;
        let n = if j == bands { k - placed } else { (ideal.round() as usize).clamp(1, k - placed - (bands - j)) };
        carry = ideal - n as f64;
        placed += n;
        counts.push(n);
    }
    let mut rings = Vec::with_capacity(counts.len());
    let mut cumulative = 0usize;
    for n in counts {
        let top = 1.0 - cumulative as f64 / k as f64;
        cumulative += n;
        rings.push((top, (1.0 - cumulative as f64 / k as f64).max(0.0), n));
    }
    rings
}

/// The direction sets a case or a command names: parsed once, where the name is read.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Scheme {
    /// `K` cells of equal solid angle over the hemisphere (`K = 1`: radiosity).
    Cells(usize),
    /// The 145-cell Klems full basis.
    Klems,
    /// The 145-patch Tregenza sky subdivision.
    Tregenza,
}

impl Scheme {
    /// The most cells a set may have: the kernel stores cell indices as 16-bit integers.
    pub const MAX_CELLS: usize = u16::MAX as usize;

    /// What [`Scheme::parse`] accepts, for error messages.
    pub const NAMES: &'static str =
        "a cell count from 1 to 65535 (cells are stored as 16-bit indices), \"klems\" or \"tregenza\"";

    /// A cell count (`"64"`, at most [`Scheme::MAX_CELLS`]), `"klems"` or `"tregenza"`.
    pub fn parse(name: &str) -> Option<Scheme> {
        match name {
            "klems" => Some(Scheme::Klems),
            "tregenza" => Some(Scheme::Tregenza),
            n => n.parse::<usize>().ok().filter(|&k| (1..=Scheme::MAX_CELLS).contains(&k)).map(Scheme::Cells),
        }
    }

    /// The name `parse` reads back.
    pub fn name(&self) -> String {
        match self {
            Scheme::Cells(k) => k.to_string(),
            Scheme::Klems => "klems".into(),
            Scheme::Tregenza => "tregenza".into(),
        }
    }

    /// The direction set the scheme names.
    pub fn set(&self) -> DirectionSet {
        match *self {
            Scheme::Cells(k) => DirectionSet::hemisphere(k),
            Scheme::Klems => DirectionSet::klems(),
            Scheme::Tregenza => DirectionSet::tregenza(),
        }
    }
}
