//! The kernel as an operator: `K = B·G`, applied factored (`G` then `B`) or formed
//! explicitly as one sparse matrix (`docs/design.md` §3).
//!
//! Solvers see both through `crate::solve::LinOp`; the factored form never builds the
//! product, the explicit one is there for norms, direct solves and export.

use super::blocks::{apply_blocks, apply_blocks_transposed};
use super::hierarchy::Hierarchy;
use super::memory::{BYTES_PER_NONZERO, Footprint};
use super::refusal::TooLarge;
use super::transport::Transport;
use crate::directions::DirectionSet;
use crate::geometry::{Mesh, NO_TWIN};
use crate::material::Block;
use crate::progress::Progress;
use sprs::{CsMat, TriMat};

/// `K = B·G`: transport `G` over `(patch, cell)` unknowns and per-material blocks `B`.
pub struct Kernel {
    /// The transport `G`, stored or the hierarchy's operator.
    pub g: Transport,
    /// The direction cells of every patch.
    pub directions: DirectionSet,
    /// One block per material.
    pub blocks: Vec<Block>,
    /// Material of each patch.
    pub patch_material: Vec<u32>,
    /// The back-to-back twin of each patch of a two-sided surface ([`crate::geometry::NO_TWIN`]
    /// otherwise): transmission carries light arriving at the twin to this patch.
    pub twin: Vec<u32>,
}

impl Kernel {
    /// The kernel of transport `g` over patches of materials `patch_material` (indices into
    /// `blocks`) and twins `twin` ([`NO_TWIN`] for none), each with the cells of
    /// `directions`: every kernel, uniform, hierarchical or read from a file, is made here.
    /// The parts must fit (a file's are checked where it is read, `io::kernel_file`).
    pub fn new(
        g: Transport,
        directions: DirectionSet,
        blocks: Vec<Block>,
        patch_material: Vec<u32>,
        twin: Vec<u32>,
    ) -> Kernel {
        debug_assert_eq!(g.rows(), patch_material.len() * directions.len());
        debug_assert_eq!(twin.len(), patch_material.len());
        debug_assert!(patch_material.iter().all(|&m| (m as usize) < blocks.len()));
        Kernel { g, directions, blocks, patch_material, twin }
    }

    /// The kernel of `g` over the patches of `mesh`.
    pub fn on_mesh(g: Transport, mesh: &Mesh, directions: DirectionSet, blocks: Vec<Block>) -> Kernel {
        let patch_material = mesh.patches.iter().map(|p| p.material).collect();
        let twin = mesh.patches.iter().map(|p| p.twin).collect();
        Kernel::new(g, directions, blocks, patch_material, twin)
    }

    /// The kernel on the current leaves of `hierarchy` (its balanced operator as `G`), with
    /// the leaves as a mesh; `progress` hears of the operator's build.
    pub fn on_leaves(hierarchy: &mut Hierarchy, progress: &dyn Progress) -> (Kernel, Mesh) {
        let g = Transport::Hierarchical(Box::new(hierarchy.operator(progress)));
        let leaves = hierarchy.leaf_mesh();
        let kernel = Kernel::on_mesh(g, &leaves, hierarchy.directions().clone(), hierarchy.blocks().to_vec());
        (kernel, leaves)
    }

    /// Number of patches `N`.
    pub fn patches(&self) -> usize {
        self.patch_material.len()
    }

    /// Number of direction cells `K`.
    pub fn cells(&self) -> usize {
        self.directions.len()
    }

    /// `y = G x`, parallel over rows.
    pub fn apply_transport(&self, x: &[f64], y: &mut [f64]) {
        self.g.apply(x, y);
    }

    /// `y = B z`, block by block: reflection of what arrives at the patch, plus
    /// transmission of what arrives at its twin.
    pub fn apply_materials(&self, z: &[f64], y: &mut [f64]) {
        apply_blocks(&self.blocks, &self.patch_material, &self.twin, self.cells(), z, y);
    }

    /// `z = Bᵀ y`, the transpose of [`Kernel::apply_materials`].
    pub fn apply_materials_transposed(&self, y: &[f64], z: &mut [f64]) {
        apply_blocks_transposed(&self.blocks, &self.patch_material, &self.twin, self.cells(), y, z);
    }

    /// True when every material block is non-negative, so that `K = B·G ≥ 0` entrywise
    /// (`G ≥ 0`: form factors, cell shares and balancing factors are).
    pub fn is_nonnegative(&self) -> bool {
        self.blocks.iter().all(Block::is_nonnegative)
    }

    /// Upper bound of the non-zeros of the explicit product `B·G`: each row `(i,d)` of `G`
    /// spreads over the `K` outgoing cells of `i` (and of its twin, when it transmits).
    pub fn explicit_nonzeros(&self) -> f64 {
        let k = self.cells();
        (0..self.g.rows())
            .map(|row| {
                let i = row / k;
                let twin = self.twin[i];
                let spread = if twin != NO_TWIN && self.blocks[self.patch_material[twin as usize] as usize].transmits()
                {
                    2
                } else {
                    1
                };
                (self.g.row_len(row) * k * spread) as f64
            })
            .sum()
    }

    /// The explicit product `B·G` as one sparse matrix, refused (with the estimate) when
    /// its upper-bound size exceeds `limit` bytes.
    pub fn explicit(&self, limit: u64) -> Result<CsMat<f64>, TooLarge> {
        let nonzeros = self.explicit_nonzeros();
        // triplets (24 bytes) and the CSR copy (16 bytes) live together while converting
        let bytes = nonzeros * (24.0 + BYTES_PER_NONZERO as f64);
        let (what, patches, cells) = ("explicit product B·G", self.patches(), self.cells());
        Footprint { what, bytes, nonzeros, patches, cells }.check(limit)?;
        let k = self.cells();
        let n = self.g.rows();
        let mut tri = TriMat::with_capacity((n, n), nonzeros as usize);
        for row in 0..n {
            let (i, d) = (row / k, row % k);
            let mut spread = |target: usize, value_of: &dyn Fn(usize) -> f64| {
                for out in 0..k {
                    let b = value_of(out);
                    if b != 0.0 {
                        self.g.for_each_in_row(row, |col, g| tri.add_triplet(target * k + out, col, b * g));
                    }
                }
            };
            let block = &self.blocks[self.patch_material[i] as usize];
            spread(i, &|out| block.at(out, d));
            let twin = self.twin[i];
            if twin != NO_TWIN {
                let back = &self.blocks[self.patch_material[twin as usize] as usize];
                spread(twin as usize, &|out| back.transmit_at(out, d).unwrap_or(0.0));
            }
        }
        Ok(tri.to_csr())
    }
}

impl Kernel {
    /// The material blocks as one sparse matrix: `B[(i,k),(i,d)] = ρ̄_{m(i)}(k,d)` and
    /// `B[(i,k),(twin(i),d)] = τ̄_{m(i)}(k,d)`, so that `K = B·G`.
    pub fn materials_matrix(&self) -> CsMat<f64> {
        let (k, n) = (self.cells(), self.patches());
        let mut tri = TriMat::new((n * k, n * k));
        for i in 0..n {
            let block = &self.blocks[self.patch_material[i] as usize];
            for (out, d) in (0..k).flat_map(|out| (0..k).map(move |d| (out, d))) {
                let reflected = block.at(out, d);
                if reflected != 0.0 {
                    tri.add_triplet(i * k + out, i * k + d, reflected);
                }
                match (self.twin[i], block.transmit_at(out, d)) {
                    (NO_TWIN, _) | (_, None) | (_, Some(0.0)) => {}
                    (twin, Some(t)) => tri.add_triplet(i * k + out, twin as usize * k + d, t),
                }
            }
        }
        tri.to_csr()
    }
}

/// The factored operator: `K x = B (G x)`, never forming the product.
pub struct Factored<'a> {
    kernel: &'a Kernel,
    scratch: std::sync::Mutex<Vec<f64>>,
}

impl<'a> Factored<'a> {
    /// The factored operator of `kernel`.
    pub fn new(kernel: &'a Kernel) -> Self {
        Factored { kernel, scratch: std::sync::Mutex::new(vec![0.0; kernel.g.rows()]) }
    }
}

impl Factored<'_> {
    /// The number of unknowns `N·K`.
    pub fn dim(&self) -> usize {
        self.kernel.g.rows()
    }

    /// `y = B (G x)`.
    pub fn apply(&self, x: &[f64], y: &mut [f64]) {
        let mut z = self.scratch.lock().unwrap_or_else(|e| e.into_inner());
        self.kernel.apply_transport(x, &mut z);
        self.kernel.apply_materials(&z, y);
    }

    /// `x = Kᵀ y = Gᵀ (Bᵀ y)`, never forming the product (`Gᵀ` scatters: serial).
    pub fn apply_transposed(&self, y: &[f64], x: &mut [f64]) {
        let mut z = self.scratch.lock().unwrap_or_else(|e| e.into_inner());
        self.kernel.apply_materials_transposed(y, &mut z);
        self.kernel.g.leaving(&z, x);
    }

    /// The kernel it applies.
    pub fn kernel(&self) -> &Kernel {
        self.kernel
    }
}

/// An explicit sparse matrix as an operator.
pub struct Explicit(pub CsMat<f64>);

impl Explicit {
    /// The number of unknowns.
    pub fn dim(&self) -> usize {
        self.0.rows()
    }

    /// `y = A x`, rows in parallel.
    pub fn apply(&self, x: &[f64], y: &mut [f64]) {
        super::uniform::spmv(&self.0, x, y);
    }
}
