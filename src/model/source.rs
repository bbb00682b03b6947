//! The source term `L0 = L_e + B·D` (`design.md` §2): the surfaces' own emission plus the
//! luminaires' direct light reflected once, on the patches of any mesh.

use crate::geometry::Mesh;
use crate::kernel::apply_blocks;
use crate::luminaire::DirectLight;
use crate::material::Block;

/// `L0 = L_e + B·D` on the patches of `mesh` (`k` cells each): each patch's own emission
/// in every cell, plus the luminaires' direct light reflected (and transmitted) once by
/// the material `blocks`.
pub fn source_term(blocks: &[Block], mesh: &Mesh, direct: &DirectLight, k: usize) -> Vec<f64> {
    let material: Vec<u32> = mesh.patches.iter().map(|p| p.material).collect();
    let twin: Vec<u32> = mesh.patches.iter().map(|p| p.twin).collect();
    let mut l0 = vec![0.0; direct.arriving.len()];
    apply_blocks(blocks, &material, &twin, k, &direct.arriving, &mut l0);
    for (cells, &emitted) in l0.chunks_mut(k).zip(&mesh.emission) {
        cells.iter_mut().for_each(|l| *l += emitted);
    }
    l0
}
