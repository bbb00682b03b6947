//! False-colour PNG maps with a legend in physical units (cd/m² for luminance images, lx
//! for illuminance grids; linear or logarithmic scale), the maps lighting engineers read
//! values off.
//!
//! Colours run dark blue → blue → cyan → green → yellow → red over the scale; pixels
//! below its bottom are drawn in the bottom colour, above its top in the top colour. A
//! signed quantity (an eigenvector of `K`, `ugo render --mode J`) has a diverging scale
//! centred on 0 instead: blue negative, white 0, red positive, symmetric about 0.

use super::IoError;
use super::atomic_png;
use super::ticks::{log_ticks, tick_label, ticks};
use crate::render::Image;
use plotters::prelude::*;
use std::path::Path;

/// How luminance maps onto the colour scale.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Scale {
    /// Linear from 0 to the top.
    Linear,
    /// Four decades below the top (or down to the smallest positive pixel).
    Log,
    /// From `−m` (blue) through 0 (white) to `m` (red), `m` the largest `|value|`.
    Signed,
}

/// Width of the legend beside the image, pixels.
pub const LEGEND_WIDTH: u32 = 170;

const STOPS: [(f64, (u8, u8, u8)); 6] = [
    (0.0, (20, 20, 90)),
    (0.2, (30, 80, 220)),
    (0.4, (40, 200, 220)),
    (0.6, (60, 200, 70)),
    (0.8, (240, 220, 40)),
    (1.0, (220, 30, 30)),
];

/// The diverging scale of [`Scale::Signed`]: 0.5 is zero.
const DIVERGING: [(f64, (u8, u8, u8)); 5] = [
    (0.0, (5, 48, 160)),
    (0.25, (100, 150, 230)),
    (0.5, (250, 250, 250)),
    (0.75, (235, 120, 90)),
    (1.0, (160, 10, 20)),
];

/// The colour of a position `t ∈ [0, 1]` on the scale.
pub fn colour(t: f64) -> RGBColor {
    interpolate(&STOPS, t)
}

/// The colour of a position `t ∈ [0, 1]` on `scale`'s colour map; shared with the
/// difference pictures (`super::difference_map`).
pub(super) fn paint(scale: Scale, t: f64) -> RGBColor {
    match scale {
        Scale::Signed => interpolate(&DIVERGING, t),
        Scale::Linear | Scale::Log => colour(t),
    }
}

fn interpolate(stops: &[(f64, (u8, u8, u8))], t: f64) -> RGBColor {
    let t = t.clamp(0.0, 1.0);
    let i = stops.iter().position(|s| s.0 >= t).unwrap_or(stops.len() - 1).max(1);
    let ((t0, a), (t1, b)) = (stops[i - 1], stops[i]);
    let f = (t - t0) / (t1 - t0);
    let mix = |x: u8, y: u8| (x as f64 + f * (y as f64 - x as f64)).round() as u8;
    RGBColor(mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}

/// The scale's bottom and top for `image`, cd/m².
pub fn bounds(image: &Image, scale: Scale) -> (f64, f64) {
    let (lo, hi) = image.range();
    let top = if hi > 0.0 { hi } else { 1.0 };
    match scale {
        Scale::Signed => {
            let m = lo.abs().max(hi.abs());
            if m.is_finite() && m > 0.0 { (-m, m) } else { (-1.0, 1.0) }
        }
        Scale::Linear => (0.0, top),
        Scale::Log => {
            let smallest = image.luminance.iter().copied().filter(|&l| l > 0.0).fold(f64::INFINITY, f64::min);
            (smallest.max(top * 1e-4).min(top / 10.0), top)
        }
    }
}

/// Position of luminance `l` on the scale `[lo, hi]`.
pub fn position(l: f64, lo: f64, hi: f64, scale: Scale) -> f64 {
    match scale {
        Scale::Linear | Scale::Signed => (l - lo) / (hi - lo),
        Scale::Log => (l.max(lo).ln() - lo.ln()) / (hi.ln() - lo.ln()),
    }
}

/// Writes the false-colour map of `image` with its legend in `unit` to `path` (PNG).
pub fn write_false_colour(path: &Path, image: &Image, scale: Scale, unit: &str) -> Result<(), IoError> {
    let (lo, hi) = bounds(image, scale);
    atomic_png(path, |png| draw(png, image, scale, (lo, hi), unit).map_err(|e| e.to_string()))
}

fn draw(
    path: &Path,
    image: &Image,
    scale: Scale,
    (lo, hi): (f64, f64),
    unit: &str,
) -> Result<(), Box<dyn std::error::Error>> {
    super::plot::register_font();
    let (w, h) = (image.width as u32, image.height.max(240) as u32);
    let root = BitMapBackend::new(path, (w + LEGEND_WIDTH, h)).into_drawing_area();
    root.fill(&WHITE)?;
    for y in 0..image.height {
        for x in 0..image.width {
            let l = image.luminance[y * image.width + x];
            root.draw_pixel((x as i32, y as i32), &paint(scale, position(l, lo, hi, scale)))?;
        }
    }
    legend(&root, (w as i32 + 20, 30, h as i32 - 30), scale, (lo, hi), unit)?;
    root.present()?;
    Ok(())
}

/// The colour bar of `scale` over `[lo, hi]` at `(x, top, bottom)` pixels, its unit above
/// it and round values (`super::ticks`) beside it; shared with the grids' plans.
pub(super) fn legend(
    root: &DrawingArea<BitMapBackend, plotters::coord::Shift>,
    (x, top, bottom): (i32, i32, i32),
    scale: Scale,
    (lo, hi): (f64, f64),
    unit: &str,
) -> Result<(), Box<dyn std::error::Error>> {
    for y in top..=bottom {
        let t = (bottom - y) as f64 / (bottom - top).max(1) as f64;
        root.draw(&Rectangle::new([(x, y), (x + 30, y + 1)], paint(scale, t).filled()))?;
    }
    let style = ("sans-serif", 14).into_font().color(&BLACK);
    root.draw(&Text::new(unit.to_string(), (x, top - 22), style.clone()))?;
    let values = match scale {
        Scale::Linear | Scale::Signed => ticks(lo, hi, 6),
        Scale::Log => log_ticks(lo, hi, 9),
    };
    for value in values {
        let y = bottom - (position(value, lo, hi, scale) * (bottom - top) as f64).round() as i32;
        root.draw(&PathElement::new(vec![(x + 30, y), (x + 36, y)], BLACK))?;
        root.draw(&Text::new(tick_label(value), (x + 40, y - 7), style.clone()))?;
    }
    Ok(())
}
