//! The material side of `K = B·G` (`docs/design.md` §3, "B"): `y = B z` over patches of `K`
//! cells, reflection by each patch's block plus transmission of what arrives at its twin,
//! and its transpose `Bᵀ y` (for `Kᵀ = Gᵀ Bᵀ`, `‖K‖₁` without the product). Shared by the
//! uniform kernel and the hierarchy's leaves.

use crate::geometry::NO_TWIN;
use crate::material::Block;
use rayon::prelude::*;

/// `y = B z` over patches of `k` cells each: patch `i` reflects what arrives at it through
/// `blocks[material[i]]` and, when that block transmits, what arrives at `twin[i]`
/// ([`NO_TWIN`] for none). Shared by the uniform kernel and the hierarchy's leaves.
pub fn apply_blocks(blocks: &[Block], material: &[u32], twin: &[u32], k: usize, z: &[f64], y: &mut [f64]) {
    y.par_chunks_mut(k).enumerate().for_each(|(i, yi)| {
        let block = &blocks[material[i] as usize];
        block.apply(&z[i * k..(i + 1) * k], yi);
        let twin = twin[i] as usize;
        if block.transmits() && twin != NO_TWIN as usize {
            block.apply_transmit(&z[twin * k..(twin + 1) * k], yi);
        }
    });
}

/// `z = Bᵀ y`, the transpose of [`apply_blocks`]: patch `j` takes back through its own block
/// what it reflects and, when its twin's block transmits, what the twin sends on from it
/// (`twin` is an involution: `twin[twin[j]] = j`).
pub fn apply_blocks_transposed(blocks: &[Block], material: &[u32], twin: &[u32], k: usize, y: &[f64], z: &mut [f64]) {
    z.par_chunks_mut(k).enumerate().for_each(|(j, zj)| {
        blocks[material[j] as usize].apply_transposed(&y[j * k..(j + 1) * k], zj);
        let i = twin[j] as usize;
        if twin[j] != NO_TWIN {
            debug_assert_eq!(twin[i] as usize, j, "twins pair up");
            blocks[material[i] as usize].apply_transmit_transposed(&y[i * k..(i + 1) * k], zj);
        }
    });
}
