//! A glTF material's base colour texture as one colour (issue 38, point 4;
//! `docs/scene-format.md`, "glTF 2.0 meshes"): ugo's surfaces have one reflectance per
//! material, so the texture's image (PNG or JPEG: a file beside the glTF file, a `data:`
//! URI, or a buffer view of a `.glb`) is decoded and its texels, sRGB-encoded as glTF
//! defines, are turned linear and averaged; the alpha is ignored, as are the texture's
//! sampler and texture coordinates.

use super::files::CaseFiles;
use super::gltf_uri::uri_bytes;
use crate::material::{linear_of_srgb, reflectance_of_colour};
use gltf::image::Source;
use gltf::texture::Info;
use std::path::Path;

/// Where a glTF file's images are read from: files beside it, or its buffers.
pub(super) struct Images<'a> {
    pub file: &'a Path,
    pub buffers: &'a [Vec<u8>],
    pub files: &'a CaseFiles,
}

impl Images<'_> {
    /// The base colour `factor` times the mean of the texture `info`, and the note that it
    /// was averaged; `about` names the material in messages.
    pub fn textured(&self, about: &str, info: Info, factor: [f64; 3]) -> Result<([f64; 3], String), String> {
        let image = info.texture().source();
        let name = image_name(&image);
        let mean = self.mean_colour(&image).map_err(|e| format!("{about}: {name} of its base colour texture: {e}"))?;
        let colour = [0, 1, 2].map(|c| factor[c] * mean[c]);
        let [r, g, b] = mean;
        let note = format!(
            "{about}: its base colour texture ({name}) is averaged to a uniform reflectance (one per material, no \
             texture maps): mean linear colour [{r:.4}, {g:.4}, {b:.4}], times the baseColorFactor ρ = {:.4}",
            reflectance_of_colour(colour)
        );
        Ok((colour, note))
    }

    /// The mean linear RGB of the texels of `image`; the error says why it cannot be read.
    fn mean_colour(&self, image: &gltf::Image) -> Result<[f64; 3], String> {
        let bytes = match image.source() {
            Source::Uri { uri, .. } => uri_bytes(self.file, uri, self.files)?,
            Source::View { view, .. } => {
                let range = view.offset()..view.offset().saturating_add(view.length());
                let bytes = self.buffers.get(view.buffer().index()).and_then(|b| b.get(range));
                bytes.ok_or_else(|| format!("its buffer view #{} lies outside its buffer", view.index()))?.to_vec()
            }
        };
        let picture = image::load_from_memory(&bytes).map_err(|e| format!("cannot decode it as PNG or JPEG: {e}"))?;
        let texels = picture.to_rgb16();
        let count = texels.pixels().len();
        if count == 0 {
            return Err("it has no texels".to_string());
        }
        let mut sum = [0.0; 3];
        for texel in texels.pixels() {
            for (total, &encoded) in sum.iter_mut().zip(&texel.0) {
                *total += linear_of_srgb(f64::from(encoded) / f64::from(u16::MAX));
            }
        }
        Ok(sum.map(|s| s / count as f64))
    }
}

/// `image #i "NAME" (URI)`, for messages: its name and where it is.
fn image_name(image: &gltf::Image) -> String {
    let name = image.name().map_or(String::new(), |n| format!(" \"{n}\""));
    let place = match image.source() {
        Source::Uri { uri, .. } if !uri.starts_with("data:") => format!(" ({uri})"),
        Source::Uri { .. } => " (a data URI)".to_string(),
        Source::View { view, .. } => format!(" (buffer view #{})", view.index()),
    };
    format!("image #{}{name}{place}", image.index())
}
