//! Tests of the case-file reader (`ugo::scene`): valid scenes, parse errors, validation errors.

mod assembly;
mod copies;
mod degenerate;
mod gltf;
mod gltf_strips;
mod gltf_textures;
mod holes;
mod lengths;
mod light_scenes;
mod luminaire_arrays;
mod luminaires;
mod magnitudes;
mod obj;
mod parse_errors;
mod probes;
mod ranges;
mod rooms;
mod sky;
mod valid;
mod validation_errors;
mod window_in_wall;
mod work_plane;

use std::path::Path;
use ugo::scene::{Scene, SceneError};

/// The discretization and one material, `white`.
const BASE: &str = r#"
[discretization]
patch_size = 0.1

[[material]]
name = "white"
type = "lambert"
reflectance = 0.75
"#;

/// An emitting disc, so that scenes built on it light up.
const LAMP: &str = r#"
[[surface]]
name = "lamp"
shape = "disc"
material = "white"
center = [0, 2, 0]
normal = [0, -1, 0]
radius = 0.2
emission = { luminance = 100.0 }
"#;

/// The case file every inline scene pretends to come from.
const CASE: &str = "cases/test.toml";

fn parse(text: &str) -> Result<Scene, SceneError> {
    Scene::parse(Path::new(CASE), text.to_string())
}

/// `BASE`, `LAMP` (surface #1), then `extra`.
fn lit(extra: &str) -> String {
    format!("{BASE}{LAMP}{extra}")
}

fn rejected(text: &str) -> SceneError {
    match parse(text) {
        Ok(scene) => panic!("accepted a bad scene: {scene:#?}"),
        Err(error) => error,
    }
}

/// Checks where the error points and that its message contains every fragment.
fn assert_error(error: &SceneError, table: &str, key: &str, fragments: &[&str]) {
    assert_eq!(error.file(), Path::new(CASE), "{error}");
    assert_eq!(error.table(), table, "{error}");
    assert_eq!(error.key(), key, "{error}");
    for fragment in fragments {
        assert!(error.message().contains(fragment), "{error:?} lacks {fragment:?}");
    }
}
