//! Each group's source term on a model rebuilt after the solve (`ugo readout`,
//! `docs/light-scenes.md`, "After the solve"): from the direct light `D_g` the solve stored
//! per group (`/light_groups/direct`, `intercepted`), so that no luminaire is traced again;
//! a file solved before `D_g` was stored has its lit groups' light traced again
//! (`super::light_scenes::group_terms`), as the solve traced it.

use super::light_scenes::group_terms;
use crate::io::StoredGroup;
use crate::luminaire::DirectLight;
use crate::model::{Model, SourceTerm};
use crate::scene::{LightGroup, Scene};

/// The groups' source terms, in the order of the scene's groups (the stored ones, checked
/// alike), and the names of the groups whose luminaires were traced again: none when the
/// file holds every group's direct light, else those of the groups `lit(g)` with luminaires.
pub(super) fn stored_group_terms(
    scene: &Scene,
    model: &Model,
    stored: &[StoredGroup],
    lit: impl Fn(usize) -> bool,
) -> (Vec<SourceTerm>, Vec<String>) {
    let groups = &scene.lighting.groups;
    if let Some(direct) = stored.iter().map(|g| g.direct.clone()).collect::<Option<Vec<DirectLight>>>() {
        let least = || model.direct.least.clone();
        let term = |(g, d): (&LightGroup, DirectLight)| {
            model.source_term_from(&g.surfaces, DirectLight { least: least(), ..d })
        };
        return (groups.iter().zip(direct).map(term).collect(), Vec::new());
    }
    let traced = groups.iter().enumerate().filter(|(i, g)| lit(*i) && !g.luminaires.is_empty());
    let traced = traced.map(|(_, g)| g.name.clone()).collect();
    (group_terms(scene, model, lit), traced)
}
