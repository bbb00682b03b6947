//! The material side of `K = B·G` (`docs/design.md` §3, "B"): `y = B z` over patches of `K`
//! cells, reflection by each patch's block plus transmission of what arrives at its twin.
//! Shared by the uniform kernel and the hierarchy's leaves.

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
