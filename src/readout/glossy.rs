//! The outgoing luminance of a point on a surface whose luminance factor varies with
//! direction (Phong, GGX, mirror), `L(q, l) = Le + (1/π) ∫ ρ(l, l') L(q, l') cosθ' dω'`
//! (`docs/design.md` §5): the final gather of `final_gather.rs` (the render's too) on the solved
//! field, with the material's own factor at the point, the emitters' and luminaires' light
//! exact, and directions sampled from its lobe on a shifted Hammersley set, the stream
//! keyed by the point so a reading is reproducible. The cell-averaged factor `ρ̄(k, d)` of
//! the Lambertian readout would spread a lobe narrower than a direction cell over the whole
//! cell: the glossy Cornell floor (Phong, exponent 50) read 11.93 cd/m² from above with it
//! at K = 64, against 14.00 ± 0.04 traced (`docs/hierarchy.md`).
//!
//! The same gather gives the light a lobed surface sends towards a point that gathers
//! (`gather.rs`), piece by piece ([`has_lobe`]): the stored cell value of a glossy patch
//! holds its reflection of a lamp spread over the cell, and the glossy Cornell ceiling, a
//! third of whose light is the lamp's image in the floor, read 5.3 % low from it.

use crate::geometry::Mesh;
use crate::luminaire::Source;
use crate::material::MaterialModel;
use crate::model::Model;
use crate::random::Rng;
use crate::readout::field::Field;
use crate::readout::final_gather::{Surroundings, final_gather};
use crate::visibility::Visibility;
use glam::DVec3;

/// Directions sampled for a probe's own luminance. On a wall seen in a glossy floor the
/// gather's error at 4,096 directions is ±0.02 % (`tests/render/glossy.rs`).
pub const RAYS: usize = 16_384;

/// Directions sampled for the light a piece of a glossy surface sends towards a gathering
/// point (`gather.rs`): one piece is a small part of what the point receives.
pub const PIECE_RAYS: usize = 256;

/// True when `material` reflects alike in every direction, so that the cell-averaged
/// readout is exact for it.
pub fn is_diffuse(material: &MaterialModel) -> bool {
    matches!(material, MaterialModel::Lambert { .. })
}

/// True when the light a patch of `material` sends towards a gathering point is gathered
/// at each piece (`gather.rs`): a lobe, Phong or GGX. A mirror sends an image, which one
/// point of a piece cannot sample (so the mirror room's floor by the mirror read 131 lx
/// against 181 ± 1 traced, and 187 from the cell values): its cell values stay.
pub fn has_lobe(material: &MaterialModel) -> bool {
    material.lobe_width().is_some()
}

/// A model and its solved field as a final gather reads them.
pub struct ModelSurroundings<'a> {
    /// The model: mesh, visibility, materials, luminaires.
    pub model: &'a Model,
    /// The solved field on its patches.
    pub field: &'a Field,
    emitters: Vec<u32>,
}

impl<'a> ModelSurroundings<'a> {
    /// The surroundings of `model` lit by `field`.
    pub fn new(model: &'a Model, field: &'a Field) -> ModelSurroundings<'a> {
        ModelSurroundings { model, field, emitters: model.mesh.emitters() }
    }

    /// The outgoing luminance of patch `i` at its point `q` towards the unit `direction`,
    /// gathered over `rays` directions, cd/m².
    pub fn outgoing(&self, i: usize, q: DVec3, direction: DVec3, rays: usize) -> f64 {
        final_gather(self, i, q, direction, rays, &mut stream(q, direction))
    }

    /// Patch `j`'s stored luminance in the cell of `-w` (seen along `w`), cd/m².
    pub fn stored(&self, j: usize, w: DVec3) -> f64 {
        let directions = &self.model.kernel.directions;
        self.field.at(j, directions.lookup(self.model.mesh.patches[j].frame().local(-w)))
    }
}

/// The random stream of a gather at `q` towards `direction`: keyed by both, so that a
/// reading is reproducible.
pub fn stream(q: DVec3, direction: DVec3) -> Rng {
    Rng::keyed(q.to_array().iter().fold(direction.x.to_bits(), |h, x| h.rotate_left(17) ^ x.to_bits()))
}

impl Surroundings for ModelSurroundings<'_> {
    fn mesh(&self) -> &Mesh {
        &self.model.mesh
    }

    fn visibility(&self) -> &Visibility {
        &self.model.visibility
    }

    fn material(&self, patch: usize) -> &MaterialModel {
        &self.model.materials[self.model.mesh.patches[patch].material as usize]
    }

    fn emitters(&self) -> &[u32] {
        &self.emitters
    }

    fn sources(&self) -> &[Source] {
        &self.model.sources
    }

    fn met(&self, q: DVec3, w: DVec3, face: u32) -> Option<(usize, f64)> {
        let model = self.model;
        let sphere = model.kernel.directions.is_sphere();
        let (j, _) = model.faces.landing_patch(&model.mesh, &model.visibility, q, w, face, sphere)?;
        Some((j, self.stored(j, w)))
    }
}
