//! A field and the light it was solved under (`docs/design.md` §5, the gather `I_d(p) + D_d(p)`
//! and the emission `L_e`; `docs/light-scenes.md`, "Readings shared by the light scenes"):
//! what a gather at a point needs besides the geometry. Several fields of one model (a
//! case's light groups) are gathered at once, each piece's rays and factors shared and its
//! light weighed by every field (`gather.rs`, `luminance::gathered_each`): the residual
//! samples of the groups' error bars cost one gather a direction, not one per group.
//!
//! A field under light other than the model's own is only sound where the gather reads
//! nothing but cell values, emission and the sources' direct light: a glossy piece's final
//! gather, a mirror's images and a transmitter's back read the model's own sources. So
//! [`Lit::apart`] is refused on a model with any of those ([`plain`]).

use super::field::Field;
use super::glossy::is_diffuse;
use crate::luminaire::Source;
use crate::model::Model;

/// A field and its light: the sources whose direct light a point receives, and the
/// surfaces' emitted luminance per patch.
#[derive(Clone, Copy)]
pub struct Lit<'a> {
    pub(super) field: &'a Field,
    pub(super) sources: &'a [Source],
    pub(super) emission: &'a [f64],
}

impl<'a> Lit<'a> {
    /// `field` under `model`'s own light.
    pub fn own(model: &'a Model, field: &'a Field) -> Lit<'a> {
        Lit { field, sources: &model.sources, emission: &model.mesh.emission }
    }

    /// `field` under `sources` and `emission` (one per patch of `model`); none when `model`
    /// is not [`plain`], or `emission` does not fit its patches.
    pub fn apart(model: &Model, field: &'a Field, sources: &'a [Source], emission: &'a [f64]) -> Option<Lit<'a>> {
        (plain(model) && emission.len() == model.mesh.patches.len()).then_some(Lit { field, sources, emission })
    }
}

/// True when every surface of `model` is Lambertian and opaque and it has no plane mirror
/// carried by images: a gather there reads only cell values, emission and direct light.
pub fn plain(model: &Model) -> bool {
    let lambertian = model.materials.iter().all(is_diffuse);
    let opaque = !model.kernel.blocks.iter().any(|b| b.transmits());
    lambertian && opaque && model.mirrors.is_empty()
}
