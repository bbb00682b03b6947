//! A stored solution made ready for rendering: its patches and field with the material
//! blocks and the luminaires of its stored scene.

use crate::io::StoredSolution;
use crate::luminaire::Source;
use crate::render::LitScene;

/// The solution ready for rendering (flat shading).
pub fn lit_scene(stored: StoredSolution) -> LitScene {
    let blocks = stored.scene.materials.iter().map(|m| m.model.block(&stored.directions)).collect();
    let sources = stored.scene.luminaires.iter().map(Source::of).collect();
    LitScene::new(stored.mesh, stored.directions, stored.luminance, blocks).with_luminaires(sources)
}
