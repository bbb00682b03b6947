//! Linear OpenEXR images in cd/m²: one 32-bit float channel `Y` (luminance).

use crate::render::Image;
use anyhow::{Result, anyhow};
use exr::prelude::{AnyChannel, AnyChannels, Encoding, FlatSamples, Layer, LayerAttributes, SmallVec, WritableImage};
use std::path::Path;

/// Writes `image` to `path` (through `path.tmp`, renamed when complete).
pub fn write_exr(path: &Path, image: &Image) -> Result<()> {
    let samples: Vec<f32> = image.luminance.iter().map(|&l| l as f32).collect();
    let channel = AnyChannel::new("Y", FlatSamples::F32(samples));
    let mut attributes = LayerAttributes::named("luminance");
    attributes.comments = Some("luminance, cd/m2 (ugo render)".into());
    let layer = Layer::new(
        (image.width, image.height),
        attributes,
        Encoding::SMALL_LOSSLESS,
        AnyChannels::sort(SmallVec::from_vec(vec![channel])),
    );
    super::atomic(path, |tmp| {
        exr::prelude::Image::from_layer(layer)
            .write()
            .to_file(tmp)
            .map_err(|e| anyhow!("cannot write {}: {e}", tmp.display()))
    })
}
