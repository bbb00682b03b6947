//! Linear OpenEXR images in cd/m²: one 32-bit float channel `Y` (luminance), written and
//! read back (`ugo agree` compares traced images with rendered ones).

use super::IoError;
use crate::render::Image;
use exr::prelude::{AnyChannel, AnyChannels, Encoding, FlatSamples, Layer, LayerAttributes, SmallVec, WritableImage};
use std::path::Path;

/// Writes `image` to `path` (through `path.tmp`, renamed when complete).
pub fn write_exr(path: &Path, image: &Image) -> Result<(), IoError> {
    write_exr_as(path, image, "luminance, cd/m2 (ugo render)")
}

/// [`write_exr`] with another description in the layer's comments.
pub fn write_exr_as(path: &Path, image: &Image, comments: &str) -> Result<(), IoError> {
    let samples: Vec<f32> = image.luminance.iter().map(|&l| l as f32).collect();
    let channel = AnyChannel::new("Y", FlatSamples::F32(samples));
    let mut attributes = LayerAttributes::named("luminance");
    attributes.comments = Some(comments.into());
    let layer = Layer::new(
        (image.width, image.height),
        attributes,
        Encoding::SMALL_LOSSLESS,
        AnyChannels::sort(SmallVec::from_vec(vec![channel])),
    );
    super::atomic(path, |tmp| exr::prelude::Image::from_layer(layer).write().to_file(tmp).map_err(|e| e.to_string()))
}

/// The channel `Y` of the first layer of an EXR file, as an image in cd/m².
pub fn read_exr(path: &Path) -> Result<Image, IoError> {
    crate::scene::regular_file(path).map_err(|e| IoError::read(path, e))?;
    let image = exr::prelude::read_first_flat_layer_from_file(path)
        .map_err(|e| IoError::read(path, format!("not OpenEXR: {e}")))?;
    let layer = &image.layer_data;
    let channel = layer
        .channel_data
        .list
        .iter()
        .find(|c| c.name == *"Y")
        .ok_or_else(|| IoError::read(path, "no luminance channel Y"))?;
    let luminance = channel.sample_data.values_as_f32().map(f64::from).collect();
    Ok(Image { width: layer.size.0, height: layer.size.1, luminance })
}
