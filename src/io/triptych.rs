//! The lecture's reflection-order pictures: images of the partial sums `Σ_{m≤n} KᵐL0`
//! side by side in one PNG, each captioned, all tone-mapped with the same exposure so
//! that the missing light shows.

use super::IoError;
use super::srgb;
use crate::render::Image;
use plotters::prelude::*;
use std::path::Path;

/// Height of the caption strip above each panel, pixels.
pub const CAPTION_HEIGHT: u32 = 36;

/// Writes `panels` (caption, image; all the same size) side by side to `path` (PNG), with
/// `exposure` cd/m² shown as white.
pub fn write_triptych(path: &Path, panels: &[(String, Image)], exposure: f64) -> Result<(), IoError> {
    super::atomic_png(path, |png| draw(png, panels, exposure).map_err(|e| e.to_string()))
}

fn draw(path: &Path, panels: &[(String, Image)], exposure: f64) -> Result<(), Box<dyn std::error::Error>> {
    super::plot::register_font();
    let (w, h) = panels.first().map_or((0, 0), |(_, i)| (i.width as u32, i.height as u32));
    let root = BitMapBackend::new(path, (w * panels.len() as u32, h + CAPTION_HEIGHT)).into_drawing_area();
    root.fill(&WHITE)?;
    for (p, (caption, image)) in panels.iter().enumerate() {
        let left = (p as u32 * w) as i32;
        root.draw(&Text::new(caption.clone(), (left + 10, 9), ("sans-serif", 20).into_font().color(&BLACK)))?;
        for y in 0..image.height {
            for x in 0..image.width {
                let v = (srgb(image.luminance[y * image.width + x] / exposure) * 255.0).round() as u8;
                root.draw_pixel((left + x as i32, CAPTION_HEIGHT as i32 + y as i32), &RGBColor(v, v, v))?;
            }
        }
    }
    root.present()?;
    Ok(())
}
