//! The one estimate of what a model will cost (issue 18, item 3): from the surfaces alone,
//! before anything is meshed (a `patch_size` of 1e-12 m or 10⁹ direction cells must be
//! refused with their figures, not found out by an allocation that aborts), or counted on
//! a mesh once it is made. Either is checked against the memory limit by
//! `super::refusal` and refused with [`super::TooLarge`].
//!
//! Closed forms: each surface's elements at edge length `h` are counted without making them
//! (`geometry::element_count`: `nu × nv` of a grid, `m²` per triangle; twice for a
//! two-sided surface). Facing pairs are counted between the scene's coarsest elements (one
//! per rectangle, box face, OBJ triangle, …), each standing for its share of its surface's
//! fine elements by area: `Σ_(a<b facing) w_a w_b` (on a mesh, every patch with weight 1),
//! over all pairs up to 4,000 elements, else from a fixed sample of pairs drawn by weight.
//! Pairs inside one coarse element are coplanar and do not count (on a sphere's 32 coarse
//! pieces this misses about 1/32 of the pairs).
//!
//! The non-zeros of `G` are twice the facing pairs times the cell pairs `(d, m)` one pair
//! of patches spreads over: a patch seen under solid angle `Ω` overlaps about
//! `(1 + √(Ω/ω))²` cells of solid angle `ω = 2π/K` on each side, at most `K²` pairs in all
//! ([`pieces`]). Occlusion can only lower it. The mesh, the solver's vectors and the
//! materials' `K × K` blocks are added.
//!
//! For the hierarchical kernel only the roots (elements of `root_size`) and the most leaves
//! (the uniform mesh at `patch_size / 2`: a leaf splits while longer than `patch_size`) are known
//! before refinement; its links are checked
//! against the limit after each pass.

use super::memory::{ASSEMBLY_BYTES_PER_PAIR, BYTES_PER_NONZERO};
use crate::directions::DirectionSet;
use crate::geometry::{ConvexPolygon, Mesh, Patch, Surface, element_count, facing};
use crate::random::Rng;
use rayon::prelude::*;

/// Bytes of one patch at the mesh's peak, the building of its ray caster: the patch, its
/// polygon as tessellated, its emission, and the BVH's build over its two triangles,
/// [`BVH_BUILD_BYTES_PER_PATCH`].
const BYTES_PER_PATCH: f64 =
    (std::mem::size_of::<Patch>() + std::mem::size_of::<ConvexPolygon>() + 8 + BVH_BUILD_BYTES_PER_PATCH) as f64;
/// What obvhs's build of the ray caster adds at its peak per patch of quads, bytes:
/// measured 766,288 kB of peak resident memory over the mesh's 531,252 kB for the furnace
/// box's 1.5·10⁶ roots (2 mm), about 520 B a patch
/// (`tests/kernel/peak.rs` holds the whole forecast to the measured peak).
const BVH_BUILD_BYTES_PER_PATCH: usize = 520;
/// Vectors of the unknowns' length a solve keeps (field, source, residual, work).
const VECTORS: f64 = 6.0;
/// Elements up to which every pair is tested.
const EXACT: usize = 4000;
/// Pairs drawn above it.
const SAMPLES: u64 = 2_000_000;

/// The cost of a model, forecast from its surfaces.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Forecast {
    /// Patches of the uniform mesh at `patch_size` (the hierarchy's roots at `root_size`).
    pub patches: f64,
    /// The most leaves of the hierarchy (its uniform mesh at `patch_size / 2`); `None` when uniform.
    pub leaves: Option<f64>,
    /// The patches of the surfaces at any size (one per OBJ triangle, rectangle, …): no
    /// coarser mesh has fewer. `None` when counted on a mesh.
    pub fewest_patches: Option<f64>,
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
    /// `G` once assembled (uniform kernel).
    pub kernel_bytes: f64,
    /// `G` while it is assembled (uniform kernel).
    pub assembly_bytes: f64,
    /// True when the pairs were sampled.
    pub sampled: bool,
    /// True when counted on the mesh, false when forecast from the surfaces.
    pub counted: bool,
}

impl Forecast {
    /// The uniform kernel of `surfaces` (with `materials` materials) meshed at
    /// `patch_size` with `directions`, before meshing.
    pub fn uniform(surfaces: &[Surface], materials: usize, patch_size: f64, directions: &DirectionSet) -> Forecast {
        let (coarse, weights) = coarse(surfaces, patch_size);
        let fewest_patches = Some(coarse.len() as f64);
        Forecast {
            counted: false,
            fewest_patches,
            ..Forecast::of_pairs(&coarse, &weights, materials, directions.len())
        }
    }

    /// The uniform kernel of `mesh`, its facing pairs counted on its patches.
    pub fn counted(mesh: &Mesh, materials: usize, directions: &DirectionSet) -> Forecast {
        Forecast::of_pairs(&mesh.patches, &vec![1.0; mesh.len()], materials, directions.len())
    }

    /// The uniform kernel over `patches`, each standing for `weights` patches of the mesh.
    fn of_pairs(patches: &[Patch], weights: &[f64], materials: usize, cells: usize) -> Forecast {
        let sampled = patches.len() > EXACT;
        let (facing_pairs, pieces) =
            if sampled { sampled_pairs(patches, weights, cells) } else { every_pair(patches, weights, cells) };
        let patches: f64 = weights.iter().sum();
        let nonzeros = 2.0 * pieces;
        let unknowns = patches * cells as f64;
        let kernel_bytes = nonzeros * BYTES_PER_NONZERO as f64 + 8.0 * (unknowns + 1.0);
        let per_pair = pieces / facing_pairs.max(1.0);
        Forecast {
            patches,
            leaves: None,
            fewest_patches: None,
            cells,
            unknowns,
            facing_pairs,
            nonzeros,
            mesh_bytes: patches * BYTES_PER_PATCH,
            vector_bytes: VECTORS * 8.0 * unknowns,
            block_bytes: (materials * cells * cells) as f64 * 8.0,
            kernel_bytes,
            assembly_bytes: kernel_bytes + facing_pairs * per_pair.max(1.0) * ASSEMBLY_BYTES_PER_PAIR,
            sampled,
            counted: true,
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
        let patches = Mesh::count(surfaces, root_size);
        let unknowns = patches * cells as f64;
        Forecast {
            patches,
            leaves: Some(Mesh::count(surfaces, patch_size / 2.0)),
            fewest_patches: Some(Mesh::count(surfaces, f64::INFINITY)),
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
            counted: false,
        }
    }

    /// Bytes the model needs at its peak (the hierarchy: before its first link).
    pub fn peak_bytes(&self) -> f64 {
        self.mesh_bytes + self.vector_bytes + self.block_bytes + self.assembly_bytes.max(self.kernel_bytes)
    }
}

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

/// Facing pairs and their cell pieces, `Σ_(a<b facing) w_a w_b`, over every pair.
fn every_pair(p: &[Patch], w: &[f64], cells: usize) -> (f64, f64) {
    (0..p.len())
        .into_par_iter()
        .map(|a| {
            (a + 1..p.len()).filter(|&b| facing(&p[a], &p[b])).fold((0.0, 0.0), |(pairs, sum), b| {
                let n = w[a] * w[b];
                (pairs + n, sum + n * pieces(&fine(&p[a], w[a]), &fine(&p[b], w[b]), cells))
            })
        })
        .reduce(|| (0.0, 0.0), |x, y| (x.0 + y.0, x.1 + y.1))
}

/// The same from a fixed sample of pairs drawn by weight, scaled to all pairs.
fn sampled_pairs(p: &[Patch], w: &[f64], cells: usize) -> (f64, f64) {
    let mut cdf = Vec::with_capacity(w.len());
    let mut total = 0.0;
    for &x in w {
        total += x;
        cdf.push(total);
    }
    let pick = |u: f64| cdf.partition_point(|&c| c < u * total).min(p.len() - 1);
    let (hits, sum) = (0..SAMPLES)
        .into_par_iter()
        .map(|s| {
            let mut rng = Rng::from_state(s);
            let (a, b) = (pick(rng.uniform()), pick(rng.uniform()));
            match a != b && facing(&p[a], &p[b]) {
                true => (1.0, pieces(&fine(&p[a], w[a]), &fine(&p[b], w[b]), cells)),
                false => (0.0, 0.0),
            }
        })
        .reduce(|| (0.0, 0.0), |x, y| (x.0 + y.0, x.1 + y.1));
    let scale = 0.5 * total * total / SAMPLES as f64;
    (hits * scale, sum * scale)
}

/// Estimated cell pairs `(d, m)` that the exchange between `a` and `b` spreads over.
fn pieces(a: &Patch, b: &Patch, cells: usize) -> f64 {
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
