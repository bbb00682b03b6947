//! Memory estimate of the kernel before any assembly, the default limit, and the refusal
//! of any matrix whose footprint exceeds it ([`Footprint::check`], [`TooLarge`]).
//!
//! The number of non-zeros of `G` is twice the number of unordered pairs of patches that
//! face each other (counted exactly up to 4,000 patches, else from a fixed sample of
//! pairs) times the cell pairs `(d, m)` one pair of patches spreads over: a patch seen
//! under solid angle `Ω` overlaps about `(1 + √(Ω/ω))²` cells of solid angle `ω = 2π/K` on
//! each side, at most `K²` pairs in all. Occlusion can only lower it.

use super::assembly::facing;
use crate::directions::DirectionSet;
use crate::geometry::{Mesh, Patch};
use crate::random::Rng;
use rayon::prelude::*;
use thiserror::Error;

/// Bytes per stored non-zero of a CSR matrix (f64 value, usize column index).
pub const BYTES_PER_NONZERO: u64 = 16;
/// Transient bytes per unordered pair during assembly (row work plus symmetric rows).
const BYTES_PER_PAIR_ASSEMBLY: u64 = 24 + 2 * 16;
/// The same, as a float (`super::forecast`).
pub(super) const ASSEMBLY_BYTES_PER_PAIR: f64 = BYTES_PER_PAIR_ASSEMBLY as f64;

/// What the kernel of a mesh will cost.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Estimate {
    /// Patches of the mesh, `N`.
    pub patches: usize,
    /// Direction cells per patch, `K`.
    pub cells: usize,
    /// Unknowns of the system, `N·K`.
    pub unknowns: usize,
    /// Unordered pairs of patches facing each other.
    pub facing_pairs: f64,
    /// Non-zeros of `G` (and of the explicit `B·G`).
    pub nonzeros: f64,
    /// Peak bytes while assembling `G`.
    pub assembly_bytes: f64,
    /// Bytes of `G` once assembled.
    pub kernel_bytes: f64,
    /// True when the pair count was sampled rather than counted.
    pub sampled: bool,
}

impl Estimate {
    /// The estimate for `mesh` with `directions`: facing pairs counted exactly up to 4000 patches,
    /// sampled beyond.
    pub fn of(mesh: &Mesh, directions: &DirectionSet) -> Estimate {
        let n = mesh.len();
        let cells = directions.len();
        let sampled = n > 4000;
        let (facing_pairs, pieces) = if sampled { sample_facing(mesh, cells) } else { count_facing(mesh, cells) };
        let k2 = pieces / facing_pairs.max(1.0);
        let nonzeros = 2.0 * pieces;
        let kernel_bytes = nonzeros * BYTES_PER_NONZERO as f64 + 8.0 * (n * cells + 1) as f64;
        Estimate {
            patches: n,
            cells,
            unknowns: n * cells,
            facing_pairs,
            nonzeros,
            assembly_bytes: kernel_bytes + facing_pairs * k2.max(1.0) * BYTES_PER_PAIR_ASSEMBLY as f64,
            kernel_bytes,
            sampled,
        }
    }

    /// The peak memory of assembling and keeping `G`, bytes.
    pub fn peak_bytes(&self) -> f64 {
        self.assembly_bytes.max(self.kernel_bytes)
    }
}

/// Facing unordered pairs and their estimated cell pieces, counted over all pairs.
fn count_facing(mesh: &Mesh, cells: usize) -> (f64, f64) {
    let p = &mesh.patches;
    (0..p.len())
        .into_par_iter()
        .map(|i| {
            (i + 1..p.len())
                .filter(|&j| facing(&p[i], &p[j]))
                .fold((0.0, 0.0), |(n, s), j| (n + 1.0, s + pieces(&p[i], &p[j], cells)))
        })
        .reduce(|| (0.0, 0.0), |a, b| (a.0 + b.0, a.1 + b.1))
}

/// The same from a fixed sample of pairs, scaled to all pairs.
fn sample_facing(mesh: &Mesh, cells: usize) -> (f64, f64) {
    const SAMPLES: u64 = 2_000_000;
    let n = mesh.len() as u64;
    let (hits, sum) = (0..SAMPLES)
        .into_par_iter()
        .map(|s| {
            let h = Rng::from_state(s).next_u64();
            let (i, j) = ((h % n) as usize, ((h >> 32) % n) as usize);
            let (a, b) = (&mesh.patches[i], &mesh.patches[j]);
            if i != j && facing(a, b) { (1.0, pieces(a, b, cells)) } else { (0.0, 0.0) }
        })
        .reduce(|| (0.0, 0.0), |a, b| (a.0 + b.0, a.1 + b.1));
    let scale = (n * (n - 1) / 2) as f64 / SAMPLES as f64;
    (hits * scale, sum * scale)
}

/// Estimated cell pairs `(d, m)` that the exchange between `a` and `b` spreads over.
pub(super) fn pieces(a: &Patch, b: &Patch, cells: usize) -> f64 {
    if cells == 1 {
        return 1.0;
    }
    let cell = std::f64::consts::TAU / cells as f64;
    let r = b.centroid - a.centroid;
    let r2 = r.length_squared();
    let seen = |p: &Patch, dir: glam::DVec3| (p.area * p.normal.dot(dir).abs() / r2).min(std::f64::consts::TAU);
    let dir = r / r2.sqrt();
    let spread = |omega: f64| (1.0 + (omega / cell).sqrt()).powi(2);
    (spread(seen(b, dir)) * spread(seen(a, dir))).min((cells * cells) as f64)
}

/// Half of the machine's physical memory (from `/proc/meminfo`), or 8 GiB where unknown.
pub fn default_limit() -> u64 {
    let total_kib = std::fs::read_to_string("/proc/meminfo")
        .ok()
        .and_then(|s| s.lines().find(|l| l.starts_with("MemTotal:"))?.split_whitespace().nth(1)?.parse::<u64>().ok());
    total_kib.map_or(8 << 30, |k| k * 1024 / 2)
}

const GIB: f64 = (1u64 << 30) as f64;

/// A matrix refused before allocation because it would not fit in the memory limit.
#[derive(Debug, Clone, PartialEq, Error)]
#[error(
    "the {what} would need about {need:.2} GiB ({nonzeros:.3e} non-zeros for {patches} patches × {cells} \
     cells), over the limit of {limit:.2} GiB. Ways out: a coarser patch_size (memory grows as \
     patch_size⁻⁴), fewer direction cells, the factored operator instead of the explicit product, \
     or a higher --memory-limit if the machine has the RAM"
)]
pub struct TooLarge {
    /// What was refused, as the message names it (e.g. "kernel G").
    pub what: &'static str,
    /// GiB.
    pub need: f64,
    /// GiB.
    pub limit: f64,
    /// Non-zeros it would hold.
    pub nonzeros: f64,
    /// Patches of the mesh.
    pub patches: usize,
    /// Direction cells per patch.
    pub cells: usize,
}

/// What a stored matrix would hold, checked against a memory limit.
#[derive(Debug, Clone, Copy)]
pub struct Footprint {
    /// What the matrix is, as the refusal names it.
    pub what: &'static str,
    /// Bytes it would take.
    pub bytes: f64,
    /// Non-zeros it would hold.
    pub nonzeros: f64,
    /// Patches of the mesh.
    pub patches: usize,
    /// Direction cells per patch.
    pub cells: usize,
}

impl Footprint {
    /// `Ok` when the footprint fits in `limit` bytes, else [`TooLarge`] with it.
    pub fn check(self, limit: u64) -> Result<(), TooLarge> {
        if self.bytes <= limit as f64 {
            return Ok(());
        }
        Err(TooLarge {
            what: self.what,
            need: self.bytes / GIB,
            limit: limit as f64 / GIB,
            nonzeros: self.nonzeros,
            patches: self.patches,
            cells: self.cells,
        })
    }
}
