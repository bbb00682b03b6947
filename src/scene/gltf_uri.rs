//! The bytes a URI of a glTF file names (issue 38, point 4; `docs/scene-format.md`, "glTF
//! 2.0 meshes"), for its buffers (`gltf.rs`) and its images (`gltf_texture.rs`): a base64
//! `data:` URI decoded, or a file beside the glTF file read.

use super::files::CaseFiles;
use base64::Engine;
use std::path::Path;

/// The bytes a URI of the glTF `file` names: a base64 `data:` URI, or a file beside it
/// (`%20` decoded, read through `files`, so that a solution file keeps a copy).
pub(super) fn uri_bytes(file: &Path, uri: &str, files: &CaseFiles) -> Result<Vec<u8>, String> {
    match uri.strip_prefix("data:") {
        Some(data) => {
            let base64 = data.split_once(";base64,").map(|(_, text)| text).ok_or("a data URI not in base64")?;
            base64::engine::general_purpose::STANDARD.decode(base64).map_err(|e| format!("bad base64 ({e})"))
        }
        None => {
            let name = urlencoding::decode(uri).map_err(|e| format!("the URI {uri}: {e}"))?;
            let path = file.parent().unwrap_or(Path::new("")).join(&*name);
            files.read(&path).map_err(|e| format!("cannot open {}: {e}", path.display()))
        }
    }
}
