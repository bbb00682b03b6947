//! A model lit by some of its emitters (`docs/design.md` §1: the field is linear in `L0`): the
//! source term of a group of luminaires and emitting surfaces alone, on the model's fixed
//! mesh and kernel, and the model relit by another set of sources, so that every readout
//! of a field (probes, grids, energy) reads a light scene as it reads the case's own light.

use super::source::{SourceTerm, source_term_with};
use super::system::Model;
use crate::luminaire::{DirectLight, Source, direct_light};

impl Model {
    /// The source term of the luminaires `luminaires` (indices into `sources`) and the
    /// surfaces `surfaces` (indices into the scene's surfaces) alone, at their output in the
    /// model. The luminaires' direct light is integrated on the model's patches with its ray
    /// caster, each shadow edge cut as far as the model's own light was
    /// (`DirectLight::least`: six levels deep for the uniform kernel, down to the oracle's
    /// `ε` on the hierarchy's leaves), so that the groups' light adds up to the model's.
    pub fn source_term_of(&self, luminaires: &[usize], surfaces: &[usize]) -> SourceTerm {
        let members: Vec<Source> = luminaires.iter().filter_map(|&i| self.sources.get(i).cloned()).collect();
        let mut direct = direct_light(
            &members,
            &self.mesh,
            &self.visibility,
            &self.kernel.directions,
            &self.direct.least,
            &self.mirrors,
        );
        let mut intercepted = vec![0.0; self.sources.len()];
        for (&i, &flux) in luminaires.iter().zip(&direct.intercepted) {
            intercepted[i] = flux;
        }
        direct.intercepted = intercepted;
        self.source_term_from(surfaces, direct)
    }

    /// The source term of the surfaces `surfaces` (indices into the scene's surfaces) and
    /// of luminaires whose direct light on the model's patches is `direct` (integrated
    /// already, as [`Model::source_term_of`] integrates it, or as a solve stored it).
    pub fn source_term_from(&self, surfaces: &[usize], direct: DirectLight) -> SourceTerm {
        let mut lit = vec![false; self.mesh.patches.iter().map(|p| p.surface as usize + 1).max().unwrap_or(0)];
        surfaces.iter().for_each(|&s| lit.get_mut(s).into_iter().for_each(|l| *l = true));
        let emission = self
            .mesh
            .patches
            .iter()
            .zip(&self.mesh.emission)
            .map(|(p, &e)| if lit[p.surface as usize] { e } else { 0.0 });
        let emission: Vec<f64> = emission.collect();
        let l0 = source_term_with(&self.kernel.blocks, &self.mesh, &emission, &direct, self.kernel.cells());
        SourceTerm { emission, direct, l0 }
    }

    /// The model's own source term less that of the luminaires `luminaires` and the
    /// surfaces `surfaces` ([`Model::source_term_of`]): the source term of every other
    /// emitter, for the cost of integrating those. Each source's light is integrated on its
    /// own, so this equals the others' source term integrated afresh to round-off.
    pub fn source_term_without(&self, luminaires: &[usize], surfaces: &[usize]) -> SourceTerm {
        let own = SourceTerm { emission: self.mesh.emission.clone(), direct: self.direct.clone(), l0: self.l0.clone() };
        let left_out = self.source_term_of(luminaires, surfaces);
        let mut rest = SourceTerm::superpose(&[(1.0, &own), (-1.0, &left_out)]);
        rest.direct.rays = left_out.direct.rays;
        rest
    }

    /// Puts `sources` (the placed luminaires, one per luminaire of the model) and `term`
    /// in place of the model's own emitters and returns those.
    pub fn relight(&mut self, sources: Vec<Source>, term: SourceTerm) -> (Vec<Source>, SourceTerm) {
        let sources = std::mem::replace(&mut self.sources, sources);
        let emission = std::mem::replace(&mut self.mesh.emission, term.emission);
        let direct = std::mem::replace(&mut self.direct, term.direct);
        let l0 = std::mem::replace(&mut self.l0, term.l0);
        (sources, SourceTerm { emission, direct, l0 })
    }
}
