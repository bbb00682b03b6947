//! What a model will cost, from the surfaces alone, before anything is meshed (issue 18,
//! item 3): a `patch_size` of 1e-12 m or 10⁹ direction cells must be refused with their
//! figures, not found out by an allocation that aborts.
//!
//! Closed forms: each surface's elements at edge length `h` are counted without making them
//! (`geometry::element_count`: `nu × nv` of a grid, `m²` per triangle; twice for a
//! two-sided surface). Facing pairs are counted between the scene's coarsest elements (one
//! per rectangle, box face, OBJ triangle, …), each standing for its share of its surface's
//! fine elements by area: `Σ_(a<b facing) w_a w_b`, over all pairs up to 2,000 coarse
//! elements, else from a fixed sample of pairs drawn by weight. Pairs inside one coarse
//! element are coplanar and do not count (on a sphere's 32 coarse pieces this misses about
//! 1/32 of the pairs). The cell pieces per pair, bytes per non-zero and the assembly's
//! transient bytes are [`super::memory::Estimate`]'s; the mesh, the solver's vectors and
//! the materials' `K × K` blocks are added.
//!
//! For the hierarchical kernel only the roots (elements of `root_size`) and the most leaves
//! (the uniform mesh at `patch_size / 2`: a leaf splits while longer than `patch_size`) are known
//! before refinement; its links are checked
//! against the limit after each pass.

use super::assembly::facing;
use super::memory::pieces;
use crate::directions::DirectionSet;
use crate::geometry::{Mesh, Patch, Surface, element_count};
use crate::random::Rng;

/// Bytes of one patch with its share of the ray caster and the face table.
const BYTES_PER_PATCH: f64 = (std::mem::size_of::<Patch>() + 160) as f64;
/// Vectors of the unknowns' length a solve keeps (field, source, residual, work).
const VECTORS: f64 = 6.0;
/// Coarse elements up to which every pair is tested.
const EXACT: usize = 2000;
/// Pairs drawn above it.
const SAMPLES: u64 = 400_000;
const GIB: f64 = (1u64 << 30) as f64;

/// The cost of a model, forecast from its surfaces.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Forecast {
    /// Patches of the uniform mesh at `patch_size` (the hierarchy's roots at `root_size`).
    pub patches: f64,
    /// The most leaves of the hierarchy (its uniform mesh at `patch_size / 2`); `None` when uniform.
    pub leaves: Option<f64>,
    /// Direction cells per patch.
    pub cells: usize,
    /// Unknowns of the system, patches (or leaves) × cells.
    pub unknowns: f64,
    /// Unordered pairs of patches facing each other (uniform kernel).
    pub facing_pairs: f64,
    /// Non-zeros of `G` (uniform kernel; 0 for the hierarchy, whose links are not known).
    pub nonzeros: f64,
    /// Bytes of the patches themselves.
    pub mesh_bytes: f64,
    /// The solver's vectors of the unknowns' length.
    pub vector_bytes: f64,
    /// The materials' `K × K` blocks.
    pub block_bytes: f64,
    /// `G` once assembled (explicit).
    pub kernel_bytes: f64,
    /// `G` while it is assembled (explicit).
    pub assembly_bytes: f64,
    /// True when the pairs were sampled.
    pub sampled: bool,
}

impl Forecast {
    /// The uniform kernel of `surfaces` (with `materials` materials) meshed at
    /// `patch_size` with `directions`.
    pub fn uniform(surfaces: &[Surface], materials: usize, patch_size: f64, directions: &DirectionSet) -> Forecast {
        let cells = directions.len();
        let (coarse, weights) = coarse(surfaces, patch_size);
        let patches: f64 = weights.iter().sum();
        let (facing_pairs, pieces) = if coarse.len() <= EXACT {
            every_pair(&coarse, &weights, cells)
        } else {
            sampled_pairs(&coarse, &weights, cells)
        };
        let nonzeros = 2.0 * pieces;
        let unknowns = patches * cells as f64;
        let kernel_bytes = nonzeros * super::memory::BYTES_PER_NONZERO as f64 + 8.0 * (unknowns + 1.0);
        let per_pair = pieces / facing_pairs.max(1.0);
        Forecast {
            patches,
            leaves: None,
            cells,
            unknowns,
            facing_pairs,
            nonzeros,
            mesh_bytes: patches * BYTES_PER_PATCH,
            vector_bytes: VECTORS * 8.0 * unknowns,
            block_bytes: (materials * cells * cells) as f64 * 8.0,
            kernel_bytes,
            assembly_bytes: kernel_bytes + facing_pairs * per_pair.max(1.0) * super::memory::ASSEMBLY_BYTES_PER_PAIR,
            sampled: coarse.len() > EXACT,
        }
    }

    /// The hierarchical kernel: roots at `root_size`, leaves split while their longest edge
    /// exceeds `patch_size`, so no leaf is smaller than half of it: at most the uniform mesh
    /// at `patch_size / 2`.
    pub fn hierarchical(
        surfaces: &[Surface],
        materials: usize,
        root_size: f64,
        patch_size: f64,
        directions: &DirectionSet,
    ) -> Forecast {
        let cells = directions.len();
        let count = |h: f64| -> f64 {
            surfaces.iter().map(|s| element_count(&s.shape, h) * if s.two_sided { 2.0 } else { 1.0 }).sum()
        };
        let patches = count(root_size);
        let unknowns = patches * cells as f64;
        Forecast {
            patches,
            leaves: Some(count(patch_size / 2.0)),
            cells,
            unknowns,
            facing_pairs: 0.0,
            nonzeros: 0.0,
            mesh_bytes: patches * BYTES_PER_PATCH,
            vector_bytes: VECTORS * 8.0 * unknowns,
            block_bytes: (materials * cells * cells) as f64 * 8.0,
            kernel_bytes: 0.0,
            assembly_bytes: 0.0,
            sampled: false,
        }
    }

    /// Bytes the model needs at its peak (the hierarchy: before its first link).
    pub fn peak_bytes(&self) -> f64 {
        self.mesh_bytes + self.vector_bytes + self.block_bytes + self.assembly_bytes.max(self.kernel_bytes)
    }

    /// `Ok` when the peak fits in `limit` bytes, else the refusal with every figure.
    pub fn check(&self, limit: u64) -> Result<(), OverLimit> {
        match self.peak_bytes() <= limit as f64 {
            true => Ok(()),
            false => Err(OverLimit { forecast: *self, limit }),
        }
    }
}

/// A model refused before meshing because its forecast exceeds the memory limit.
#[derive(Debug, Clone, PartialEq)]
pub struct OverLimit {
    /// The forecast refused.
    pub forecast: Forecast,
    /// Bytes.
    pub limit: u64,
}

impl std::fmt::Display for OverLimit {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let e = &self.forecast;
        write!(
            f,
            "the model would need about {}, over the limit of {}: ",
            gib(e.peak_bytes()),
            gib(self.limit as f64)
        )?;
        write!(f, "{:.3e} patches × {} direction cells = {:.3e} unknowns", e.patches, e.cells, e.unknowns)?;
        match e.leaves {
            None => write!(
                f,
                ", {:.3e} facing pairs, {:.3e} non-zeros of G ({} to assemble)",
                e.facing_pairs,
                e.nonzeros,
                gib(e.assembly_bytes.max(e.kernel_bytes))
            )?,
            Some(leaves) => write!(f, " (roots of the hierarchy; at most {leaves:.3e} leaves)")?,
        }
        write!(
            f,
            ", the mesh {}, the material blocks (K × K each) {}; estimated before meshing. Ways out: a larger \
             {}, fewer --directions, {}or a higher --memory-limit if the machine has the RAM",
            gib(e.mesh_bytes),
            gib(e.block_bytes),
            match e.leaves {
                None => "--patch-size (patches grow as patch_size⁻², the uniform kernel as patch_size⁻⁴)",
                Some(_) => "--root-size (the hierarchy's roots grow as root_size⁻²)",
            },
            if e.leaves.is_none() { "--kernel hierarchical, " } else { "" }
        )
    }
}

/// Bytes as GiB, in scientific notation past 10⁴ GiB.
fn gib(bytes: f64) -> String {
    match bytes / GIB {
        g if g < 1e4 => format!("{g:.3} GiB"),
        g => format!("{g:.3e} GiB"),
    }
}

impl std::error::Error for OverLimit {}

/// The scene's coarsest patches and the fine patches at `h` each stands for.
fn coarse(surfaces: &[Surface], h: f64) -> (Vec<Patch>, Vec<f64>) {
    let mesh = Mesh::build(surfaces, f64::INFINITY);
    let areas = mesh.surface_areas(surfaces.len());
    let fine: Vec<f64> =
        surfaces.iter().map(|s| element_count(&s.shape, h) * if s.two_sided { 2.0 } else { 1.0 }).collect();
    let weights = mesh.patches.iter().map(|p| fine[p.surface as usize] * p.area / areas[p.surface as usize]).collect();
    (mesh.patches, weights)
}

/// A fine patch of the coarse `p` standing for `w` of them.
fn fine(p: &Patch, w: f64) -> Patch {
    Patch { area: p.area / w.max(1.0), ..*p }
}

fn every_pair(p: &[Patch], w: &[f64], cells: usize) -> (f64, f64) {
    let (mut pairs, mut sum) = (0.0, 0.0);
    for a in 0..p.len() {
        for b in a + 1..p.len() {
            if facing(&p[a], &p[b]) {
                let n = w[a] * w[b];
                pairs += n;
                sum += n * pieces(&fine(&p[a], w[a]), &fine(&p[b], w[b]), cells);
            }
        }
    }
    (pairs, sum)
}

fn sampled_pairs(p: &[Patch], w: &[f64], cells: usize) -> (f64, f64) {
    let mut cdf = Vec::with_capacity(w.len());
    let mut total = 0.0;
    for &x in w {
        total += x;
        cdf.push(total);
    }
    let pick = |u: f64| cdf.partition_point(|&c| c < u * total).min(p.len() - 1);
    let mut rng = Rng::keyed(18);
    let (mut hits, mut sum) = (0.0, 0.0);
    for _ in 0..SAMPLES {
        let (a, b) = (pick(rng.uniform()), pick(rng.uniform()));
        if a != b && facing(&p[a], &p[b]) {
            hits += 1.0;
            sum += pieces(&fine(&p[a], w[a]), &fine(&p[b], w[b]), cells);
        }
    }
    let scale = 0.5 * total * total / SAMPLES as f64;
    (hits * scale, sum * scale)
}
