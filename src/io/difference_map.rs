//! The picture of a solution's image against a traced reference (`ugo agree --difference`):
//! the signed relative difference `(x − m)/m` per pixel in the diverging colours of
//! `super::false_colour` (blue low, white 0, red high), saturating at ± a scale in %, the
//! pixels whose difference lies within 2 of the reference's standard errors drawn grey, and
//! the colour bar in % beside (`super::false_colour::legend`). Small images are magnified by
//! a whole factor so that the picture is at least [`DIFFERENCE_SIDE`] pixels on its longer side.

use super::IoError;
use super::atomic_png;
use super::false_colour::{Scale, legend, paint, position};
use crate::render::Image;
use plotters::prelude::*;
use std::path::Path;

/// The longer side, pixels, below which the image is magnified.
pub const DIFFERENCE_SIDE: usize = 256;

/// The colour of a pixel whose difference lies within 2 standard errors of the reference.
pub const WITHIN_NOISE: RGBColor = RGBColor(150, 150, 150);

/// The whole factor by which a `width × height` image is magnified in the picture.
pub fn magnification(width: usize, height: usize) -> usize {
    (DIFFERENCE_SIDE / width.max(height).max(1)).max(1)
}

/// A pixel's relative difference `(x − m)/m` in %, or `None` when it lies within 2 standard
/// errors `s` of the reference. A reference of 0 (no relative difference) counts as ±∞.
pub fn relative_difference(x: f64, m: f64, s: f64) -> Option<f64> {
    let d = x - m;
    if d.abs() <= 2.0 * s.abs() {
        return None;
    }
    Some(if m > 0.0 { 100.0 * d / m } else { d.signum() * f64::INFINITY })
}

/// Writes the picture of `solution` against the reference `mean` with standard errors
/// `error` (three images of one size), saturating at ±`scale` %, to `path` (PNG).
pub fn write_difference(path: &Path, solution: &Image, mean: &Image, error: &Image, scale: f64) -> Result<(), IoError> {
    let sizes = [solution, mean, error].map(|i| (i.width, i.height));
    if sizes[1..].iter().any(|s| *s != sizes[0]) || !(scale.is_finite() && scale > 0.0) {
        return Err(IoError::Write {
            path: path.to_path_buf(),
            why: format!("images of sizes {sizes:?} on a scale of ±{scale} %: one size and a positive scale needed"),
        });
    }
    atomic_png(path, |png| draw(png, solution, mean, error, scale).map_err(|e| e.to_string()))
}

fn draw(
    path: &Path,
    solution: &Image,
    mean: &Image,
    error: &Image,
    scale: f64,
) -> Result<(), Box<dyn std::error::Error>> {
    super::plot::register_font();
    let k = magnification(solution.width, solution.height);
    let (w, h) = ((k * solution.width) as u32, (k * solution.height).max(240) as u32);
    let root = BitMapBackend::new(path, (w + super::LEGEND_WIDTH, h)).into_drawing_area();
    root.fill(&WHITE)?;
    for y in 0..solution.height {
        for x in 0..solution.width {
            let i = y * solution.width + x;
            let colour = match relative_difference(solution.luminance[i], mean.luminance[i], error.luminance[i]) {
                None => WITHIN_NOISE,
                Some(r) => paint(Scale::Signed, position(r, -scale, scale, Scale::Signed)),
            };
            let (x0, y0) = ((k * x) as i32, (k * y) as i32);
            root.draw(&Rectangle::new([(x0, y0), (x0 + k as i32, y0 + k as i32)], colour.filled()))?;
        }
    }
    let (x, bottom) = (w as i32 + 20, h as i32 - 40);
    legend(&root, (x, 30, bottom), Scale::Signed, (-scale, scale), "(x − m)/m, %")?;
    root.draw(&Rectangle::new([(x, bottom + 12), (x + 30, bottom + 24)], WITHIN_NOISE.filled()))?;
    let style = ("sans-serif", 14).into_font().color(&BLACK);
    root.draw(&Text::new("within 2σ", (x + 40, bottom + 11), style))?;
    root.present()?;
    Ok(())
}
