//! A stored solution made ready for rendering: its patches and field with the material
//! models and the luminaires of its stored scene.

use crate::io::StoredSolution;
use crate::luminaire::Source;
use crate::render::LitScene;

/// The solution ready for rendering (flat shading).
pub fn lit_scene(stored: StoredSolution) -> LitScene {
    let sources = stored.scene.luminaires.iter().map(Source::of).collect();
    lit_scene_with(stored, sources)
}

/// [`lit_scene`] with the placed luminaires `sources` (one per luminaire of the stored
/// scene, dimmed by a light scene) in place of the scene's own.
pub fn lit_scene_with(stored: StoredSolution, sources: Vec<Source>) -> LitScene {
    let materials = stored.scene.materials.iter().map(|m| m.model.clone()).collect();
    LitScene::new(stored.mesh, stored.directions, stored.luminance, materials).with_luminaires(sources)
}
