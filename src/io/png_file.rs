//! Tone-mapped sRGB PNG images of luminance, with a sidecar `<png>.txt` stating the
//! exposure: linear scaling that maps the exposure luminance to white, clipped above,
//! then the sRGB transfer function.

use super::IoError;
use crate::render::Image;
use std::path::Path;

/// The luminance mapped to white when none is given: the 99th percentile of the pixel
/// values `luminance` (their maximum if that is zero; 1 cd/m² for none or a black image).
/// The renders give it the pixels whose samples all see surfaces: a luminaire's luminous
/// opening or the sky through a window, far brighter, would set it.
pub fn auto_exposure(luminance: &[f64]) -> f64 {
    let mut sorted: Vec<f64> = luminance.iter().copied().filter(|l| l.is_finite()).collect();
    sorted.sort_by(f64::total_cmp);
    let Some(&max) = sorted.last() else { return 1.0 };
    let p99 = sorted[((sorted.len() - 1) as f64 * 0.99).round() as usize];
    if p99 > 0.0 {
        p99
    } else if max > 0.0 {
        max
    } else {
        1.0
    }
}

/// sRGB encoding of a linear value in [0, 1].
pub fn srgb(linear: f64) -> f64 {
    let x = linear.clamp(0.0, 1.0);
    if x <= 0.003_130_8 { 12.92 * x } else { 1.055 * x.powf(1.0 / 2.4) - 0.055 }
}

/// Writes `image` as a grey sRGB PNG with `exposure` (cd/m²) as white, and the sidecar.
pub fn write_png(path: &Path, image: &Image, exposure: f64) -> Result<(), IoError> {
    let pixels: Vec<u8> = image.luminance.iter().map(|&l| (srgb(l / exposure) * 255.0).round() as u8).collect();
    let (w, h) = (image.width as u32, image.height as u32);
    super::atomic(path, |tmp| {
        ::image::save_buffer_with_format(tmp, &pixels, w, h, ::image::ExtendedColorType::L8, ::image::ImageFormat::Png)
            .map_err(|e| e.to_string())
    })?;
    let (lo, hi) = image.range();
    let note = format!(
        "ugo render: {}\nexposure (white) {exposure:.6e} cd/m2, linear then sRGB transfer, clipped above\n\
         luminance range {lo:.6e} .. {hi:.6e} cd/m2\nlinear values: the .exr of the same name\n",
        path.display()
    );
    let mut side = path.as_os_str().to_owned();
    side.push(".txt");
    super::atomic(Path::new(&side), |tmp| std::fs::write(tmp, note).map_err(|e| e.to_string()))
}
