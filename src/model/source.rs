//! The source term `L0 = L_e + B·D` (`docs/design.md` §2): the surfaces' own emission plus the
//! luminaires' direct light reflected once, on the patches of any mesh; and the source
//! term of some of the emitters alone ([`SourceTerm`]), linear in them.

use crate::geometry::Mesh;
use crate::kernel::apply_blocks;
use crate::luminaire::DirectLight;
use crate::material::Block;

/// `L0 = L_e + B·D` on the patches of `mesh` (`k` cells each): each patch's own emission
/// in every cell, plus the luminaires' direct light reflected (and transmitted) once by
/// the material `blocks`.
pub fn source_term(blocks: &[Block], mesh: &Mesh, direct: &DirectLight, k: usize) -> Vec<f64> {
    source_term_with(blocks, mesh, &mesh.emission, direct, k)
}

/// [`source_term`] with the patches' own emission `emission` in place of the mesh's.
pub fn source_term_with(blocks: &[Block], mesh: &Mesh, emission: &[f64], direct: &DirectLight, k: usize) -> Vec<f64> {
    let material: Vec<u32> = mesh.patches.iter().map(|p| p.material).collect();
    let twin: Vec<u32> = mesh.patches.iter().map(|p| p.twin).collect();
    let mut l0 = vec![0.0; direct.arriving.len()];
    apply_blocks(blocks, &material, &twin, k, &direct.arriving, &mut l0);
    for (cells, &emitted) in l0.chunks_mut(k).zip(emission) {
        cells.iter_mut().for_each(|l| *l += emitted);
    }
    l0
}

/// What some emitters put into the system of a model: the surfaces' own emission `L_e`
/// per patch, the luminaires' direct light `D` per (patch, cell) with the flux each
/// luminaire lands (zero for the luminaires not among them), and `L0 = L_e + B·D`.
#[derive(Debug, Clone, PartialEq)]
pub struct SourceTerm {
    /// The surfaces' own emission `L_e` per patch, cd/m².
    pub emission: Vec<f64>,
    /// The luminaires' direct light `D` and the flux each lands.
    pub direct: DirectLight,
    /// The source term `L0 = L_e + B·D`, `x[i·K + k]`, cd/m².
    pub l0: Vec<f64>,
}

impl SourceTerm {
    /// `Σ w·T` over the `(w, T)` of `parts` (source terms of one model): the source term of
    /// the emitters of every part, each dimmed by its `w`, since `L_e`, `D` and `L0` are
    /// linear in the emitters.
    pub fn superpose(parts: &[(f64, &SourceTerm)]) -> SourceTerm {
        let zeros = |len: fn(&SourceTerm) -> usize| vec![0.0; parts.first().map_or(0, |(_, t)| len(t))];
        let mut sum = SourceTerm {
            emission: zeros(|t| t.emission.len()),
            direct: DirectLight {
                arriving: zeros(|t| t.direct.arriving.len()),
                intercepted: zeros(|t| t.direct.intercepted.len()),
                rays: 0,
                least: parts.first().map_or_else(Vec::new, |(_, t)| t.direct.least.clone()),
            },
            l0: zeros(|t| t.l0.len()),
        };
        let add = |into: &mut [f64], w: f64, v: &[f64]| into.iter_mut().zip(v).for_each(|(s, v)| *s += w * v);
        for &(w, t) in parts {
            add(&mut sum.emission, w, &t.emission);
            add(&mut sum.direct.arriving, w, &t.direct.arriving);
            add(&mut sum.direct.intercepted, w, &t.direct.intercepted);
            add(&mut sum.l0, w, &t.l0);
            sum.direct.rays += t.direct.rays;
        }
        sum
    }
}
