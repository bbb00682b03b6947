//! The warning of mirrors reflected cell to cell (`docs/mirrors.md`): a plane mirror's
//! light is carried by images (`docs/design.md` (3.10)) only by the uniform kernel, only
//! when every luminaire is a point source, and only for a mirror that is plane, dark and
//! faces no other mirror. Any other mirror reflects through its cell block, which smears
//! its image over about a cell's angular size, `√(2π/K)` rad: the mirror room read with
//! the hierarchy put the floor by the mirror 4.9 % above `ugo trace`, outside its error
//! bar (`docs/accuracy.md`, "The mirror room's hard probes").

use crate::io::{MirrorCause, Warning};
use crate::luminaire::Source;
use crate::material::MaterialModel;
use crate::model::Model;
use crate::scene::Scene;

/// The warning for the mirror surfaces of `model` (of `scene`) that no plane mirror of the
/// kernel holds, if any.
pub(super) fn mirrors_by_cells(scene: &Scene, model: &Model) -> Option<Warning> {
    let mut surfaces: Vec<u32> = model
        .mesh
        .patches
        .iter()
        .enumerate()
        .filter(|(_, p)| matches!(scene.materials[p.material as usize].model, MaterialModel::Mirror { .. }))
        .filter(|&(i, _)| !model.mirrors.iter().any(|m| m.holds(i as u32)))
        .map(|(_, p)| p.surface)
        .collect();
    surfaces.sort_unstable();
    surfaces.dedup();
    if surfaces.is_empty() {
        return None;
    }
    let cause = if model.hierarchy.is_some() {
        MirrorCause::Hierarchy
    } else if !model.sources.iter().all(Source::mirrored_by_image) {
        MirrorCause::NotPointLight
    } else {
        MirrorCause::NotPlane
    };
    let names = surfaces.iter().map(|&s| scene.surfaces[s as usize].name.clone()).collect();
    Some(Warning::MirrorsByCells { surfaces: names, cells: model.kernel.cells(), cause })
}
