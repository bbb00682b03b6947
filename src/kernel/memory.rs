//! Memory estimate of the kernel before any assembly, and the default limit.
//!
//! The number of non-zeros of `G` is the number of ordered pairs of patches that face
//! each other (counted exactly up to 4,000 patches, else from a fixed sample of pairs)
//! times `K²`; occlusion can only lower it, so the estimate is an upper bound up to the
//! sampling error.

use super::assembly::facing;
use crate::geometry::Mesh;
use rayon::prelude::*;

/// Bytes per stored non-zero of a CSR matrix (f64 value, usize column index).
pub const BYTES_PER_NONZERO: u64 = 16;
/// Transient bytes per unordered pair during assembly (row work plus symmetric rows).
const BYTES_PER_PAIR_ASSEMBLY: u64 = 24 + 2 * 16;

/// What the kernel of a mesh will cost.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Estimate {
    pub patches: usize,
    pub cells: usize,
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
    pub fn of(mesh: &Mesh, cells: usize) -> Estimate {
        let n = mesh.len();
        let (facing_pairs, sampled) =
            if n <= 4000 { (count_facing(mesh) as f64, false) } else { (sample_facing(mesh), true) };
        let k2 = (cells * cells) as f64;
        let nonzeros = 2.0 * facing_pairs * k2;
        let kernel_bytes = nonzeros * BYTES_PER_NONZERO as f64 + 8.0 * (n * cells + 1) as f64;
        Estimate {
            patches: n,
            cells,
            unknowns: n * cells,
            facing_pairs,
            nonzeros,
            assembly_bytes: kernel_bytes + facing_pairs * k2 * BYTES_PER_PAIR_ASSEMBLY as f64,
            kernel_bytes,
            sampled,
        }
    }

    /// The peak memory of assembling and keeping `G`, bytes.
    pub fn peak_bytes(&self) -> f64 {
        self.assembly_bytes.max(self.kernel_bytes)
    }
}

fn count_facing(mesh: &Mesh) -> usize {
    let p = &mesh.patches;
    (0..p.len()).into_par_iter().map(|i| (i + 1..p.len()).filter(|&j| facing(&p[i], &p[j])).count()).sum()
}

fn sample_facing(mesh: &Mesh) -> f64 {
    const SAMPLES: u64 = 2_000_000;
    let n = mesh.len() as u64;
    let hits: u64 = (0..SAMPLES)
        .into_par_iter()
        .map(|s| {
            let h = splitmix(s);
            let (i, j) = ((h % n) as usize, ((h >> 32) % n) as usize);
            (i != j && facing(&mesh.patches[i], &mesh.patches[j])) as u64
        })
        .sum();
    hits as f64 / SAMPLES as f64 * (n * (n - 1) / 2) as f64
}

fn splitmix(mut z: u64) -> u64 {
    z = z.wrapping_add(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// Half of the machine's physical memory (from `/proc/meminfo`), or 8 GiB where unknown.
pub fn default_limit() -> u64 {
    let total_kib = std::fs::read_to_string("/proc/meminfo")
        .ok()
        .and_then(|s| s.lines().find(|l| l.starts_with("MemTotal:"))?.split_whitespace().nth(1)?.parse::<u64>().ok());
    total_kib.map_or(8 << 30, |k| k * 1024 / 2)
}
