//! The luminance of a surface point, and the luminance seen along a ray, read from the
//! solved field (`docs/design.md` §5).
//!
//! On a Lambertian surface the outgoing luminance towards `v` is `L_e + Σ_d ρ̄(k,d)
//! (I_d + D_d)`, `k` the cell of `v` and `I_d + D_d` the light arriving at the point per
//! cell (`gather.rs`), plus the light transmitted from the back of a transmitting surface:
//! `ρ̄` is exact there. A glossy surface's luminance is its final gather with its own
//! luminance factor (`glossy.rs`, [`glossy::RAYS`] directions), **relit**: the stored
//! luminance of the surfaces its lobe meets is a leaf's cell value, and where those
//! surfaces take their light from glossy ones it holds their reflections spread over a
//! cell. So [`RELIT_RAYS`] of the lobe's directions are followed once more, each to the
//! point it meets, whose own light is gathered there (a Lambertian point as above, a Phong
//! or GGX point by its final gather), and the final gather is corrected by the mean
//! difference `w (L_relit − L_stored)` over them (the same directions, sampled from one
//! stream; a mirror's one direction is relit whole). A relit point's gather cuts along
//! shadow edges more coarsely ([`RELIT_SHADOW_CUT`]): its errors average over the points.
//! A luminance meter relits each of its directions once. The glossy Cornell floor seen from
//! above, whose lobe meets the ceiling and the short block's foot 1 cm away, read 2.7 % low
//! without it (`docs/hierarchy.md`).

use crate::geometry::{Mesh, NO_TWIN};
use crate::luminaire::Source;
use crate::material::MaterialModel;
use crate::model::Model;
use crate::readout::cut::Cut;
use crate::readout::field::Field;
use crate::readout::final_gather::{Surroundings, indirect};
use crate::readout::gather::{SHADOW_CUT, arriving, arriving_each};
use crate::readout::glossy::{self, ModelSurroundings, PIECE_RAYS, has_lobe, is_diffuse, stream};
use crate::readout::lit::Lit;
use crate::visibility::{NO_FACE, Visibility};
use glam::DVec3;

/// Directions of a glossy point's lobe followed to the points they meet and gathered
/// there again. The glossy Cornell floor read −0.2 % at 32 and −0.7 % at 64, against
/// +0.6 % and −0.6 % with the lobe's component chosen at random (`docs/hierarchy.md`).
pub const RELIT_RAYS: usize = 32;

/// A relit point's gather cuts the pieces along shadow edges while their light exceeds
/// this fraction of all it would receive unoccluded (a probe's own gather: `SHADOW_CUT`,
/// 10⁻⁴): each of its uncut pieces errs by at most its share, either way, and the relit
/// points' errors average.
pub const RELIT_SHADOW_CUT: f64 = 1e-3;

/// Outgoing luminance of patch `i` at point `q` towards `direction`, from the light
/// `incident` on it per cell (and, for a transmitter, the light arriving at its back); a
/// glossy surface's by its own luminance factor instead, relit over [`RELIT_RAYS`] directions.
pub fn outgoing(model: &Model, field: &Field, i: usize, q: DVec3, direction: DVec3, incident: &[f64]) -> f64 {
    if !is_diffuse(&model.materials[model.mesh.patches[i].material as usize]) {
        return relit(model, field, i, q, direction, RELIT_RAYS);
    }
    lambertian(model, &Lit::own(model, field), i, q, direction, incident, &[])
}

/// The luminance (cd/m²) seen from `p` along the unit `v`: the outgoing luminance, gathered
/// as above, of the first surface point the ray meets, towards `p` (0 when it meets none
/// or the back of a surface); a glossy point relit over `relit_rays` directions.
pub fn seen(model: &Model, field: &Field, p: DVec3, v: DVec3, relit_rays: usize) -> f64 {
    model
        .faces
        .landing(&model.mesh, &model.visibility, p, v, NO_FACE)
        .and_then(|hit| {
            let (q, i) = (hit.point, hit.facing?);
            let s = &model.mesh.patches[i];
            if !is_diffuse(&model.materials[s.material as usize]) {
                return Some(relit(model, field, i, q, -v, relit_rays));
            }
            Some(lambertian(model, &Lit::own(model, field), i, q, -v, &arriving(model, field, q, s), &[]))
        })
        .unwrap_or(0.0)
}

/// The Lambertian luminance of patch `j`'s point `y` towards `direction`, from the light
/// gathered at `y` (its pieces along shadow edges cut at [`RELIT_SHADOW_CUT`] by the
/// field's rule, or by that of any field of `by`: `cut.rs`), cd/m².
pub fn gathered(model: &Model, field: &Field, j: usize, y: DVec3, direction: DVec3, by: &[&Field]) -> f64 {
    let cut = Cut { fraction: RELIT_SHADOW_CUT, by, sampled: 0.0 };
    gathered_each(model, &[Lit::own(model, field)], j, y, direction, &cut)[0]
}

/// [`gathered`] for each field of `lits` under its own light, the gather's rays and
/// factors shared (`lit.rs`), cut by `cut` (by the rules of all the fields of `lits` when
/// it names none).
pub fn gathered_each(model: &Model, lits: &[Lit], j: usize, y: DVec3, direction: DVec3, cut: &Cut) -> Vec<f64> {
    let s = &model.mesh.patches[j];
    let incident = arriving_each(model, lits, y, s, cut);
    lits.iter().zip(&incident).map(|(lit, e)| lambertian(model, lit, j, y, direction, e, cut.by)).collect()
}

/// The Lambertian outgoing luminance of patch `i` at `q` towards `direction` under `lit`,
/// the light through a transmitter gathered as [`arriving`] cuts it, by the rules of `by`
/// (`cut.rs`).
fn lambertian(model: &Model, lit: &Lit, i: usize, q: DVec3, direction: DVec3, incident: &[f64], by: &[&Field]) -> f64 {
    let kernel = &model.kernel;
    let patch = &model.mesh.patches[i];
    let k = kernel.directions.lookup(patch.frame().local(direction));
    let block = &kernel.blocks[kernel.patch_material[i] as usize];
    let mut l = lit.emission[i] + incident.iter().enumerate().map(|(d, e)| block.at(k, d) * e).sum::<f64>();
    if block.transmits() && patch.twin != NO_TWIN {
        let twin = &model.mesh.patches[patch.twin as usize];
        let cut = Cut { fraction: SHADOW_CUT, by, sampled: 0.0 };
        let through = arriving_each(model, std::slice::from_ref(lit), q, twin, &cut).swap_remove(0);
        l += through.iter().enumerate().map(|(d, e)| block.transmit_at(k, d).unwrap_or(0.0) * e).sum::<f64>();
    }
    l
}

/// A glossy patch `i`'s luminance at `q` towards `direction`: its final gather, corrected
/// over `relit_rays` of its directions by the light gathered again where they land.
fn relit(model: &Model, field: &Field, i: usize, q: DVec3, direction: DVec3, relit_rays: usize) -> f64 {
    let stored = ModelSurroundings::new(model, field);
    let gathered = stored.outgoing(i, q, direction, glossy::RAYS);
    if relit_rays == 0 {
        return gathered;
    }
    let again = Relit { stored: &stored };
    let rng = stream(q, direction);
    let fresh = indirect(&again, i, q, direction, relit_rays, &mut rng.clone());
    let old = indirect(&stored, i, q, direction, relit_rays, &mut rng.clone());
    gathered + fresh - old
}

/// The solved field as a final gather reads it, but with the light of every point a ray
/// meets gathered at that point: a Lambertian point's from all the light arriving there, a
/// Phong or GGX point's by its own final gather ([`PIECE_RAYS`] directions); a mirror's,
/// and the back of a surface, as stored.
struct Relit<'a> {
    stored: &'a ModelSurroundings<'a>,
}

impl Surroundings for Relit<'_> {
    fn mesh(&self) -> &Mesh {
        self.stored.mesh()
    }

    fn visibility(&self) -> &Visibility {
        self.stored.visibility()
    }

    fn material(&self, patch: usize) -> &MaterialModel {
        self.stored.material(patch)
    }

    fn emitters(&self) -> &[u32] {
        self.stored.emitters()
    }

    fn sources(&self) -> &[Source] {
        self.stored.sources()
    }

    fn met(&self, q: DVec3, w: DVec3, face: u32) -> Option<(usize, f64)> {
        let (model, field) = (self.stored.model, self.stored.field);
        let sphere = model.kernel.directions.is_sphere();
        let (j, y) = model.faces.landing_patch(&model.mesh, &model.visibility, q, w, face, sphere)?;
        let s = &model.mesh.patches[j];
        let material = self.material(j);
        let light = if s.normal.dot(w) >= 0.0 {
            self.stored.stored(j, w)
        } else if is_diffuse(material) {
            gathered(model, field, j, y, -w, &[])
        } else if has_lobe(material) {
            self.stored.outgoing(j, y, -w, PIECE_RAYS)
        } else {
            self.stored.stored(j, w)
        };
        Some((j, light))
    }
}
