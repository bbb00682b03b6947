//! What a grid's plan draws over its cells (`grid_map.rs`): the luminaires as the plan's
//! light scene has them, and the section of the surfaces by the grid's plane.
//!
//! * a luminaire at its full output is a white circle with a cross; a dimmed one (a light
//!   scene's factor other than 1) the same with its level in % beside it; one switched off
//!   (factor 0) a hollow grey circle without a cross;
//! * the section (`crate::geometry::section`): where walls, partitions and furniture cross
//!   the grid's plane, dark grey lines clipped to the plot.

use super::plan::{Frame, Layout};
use crate::luminaire::{Light, Source};
use glam::{DVec2, DVec3};
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

type Area<'a> = DrawingArea<BitMapBackend<'a>, plotters::coord::Shift>;
type Drawn = Result<(), Box<dyn std::error::Error>>;

/// The marker's radius, pixels.
const RADIUS: i32 = 7;

/// What a plan draws over its cells besides the grid's outline.
#[derive(Debug, Clone, Copy, Default)]
pub struct Overlay<'a> {
    /// The placed sources, each dimmed as the plan's light scene says (`Source::dimmed`);
    /// the point luminaires among them are drawn.
    pub sources: &'a [Source],
    /// The segments where the surfaces cross the grid's plane, m.
    pub section: &'a [[DVec3; 2]],
}

impl Overlay<'_> {
    /// The point luminaires: position and dimming factor.
    fn lamps(&self) -> impl Iterator<Item = (DVec3, f64)> + '_ {
        self.sources.iter().filter_map(|s| match &s.light {
            Light::Point { position, .. } => Some((*position, s.dimmed)),
            Light::Parallel { .. } | Light::Window { .. } => None,
        })
    }

    /// Where the point luminaires are, m.
    pub fn positions(&self) -> Vec<DVec3> {
        self.lamps().map(|(p, _)| p).collect()
    }
}

/// A marker at each luminaire over the plot: full, dimmed (with its level) or off.
pub fn draw_lamps(root: &Area, frame: &Frame, layout: &Layout, overlay: &Overlay) -> Drawn {
    let [left, top, right, bottom] = layout.plot;
    for (p, dimmed) in overlay.lamps() {
        let q = layout.pixel(frame.plan(p));
        let (x, y) = (q.x.round() as i32, q.y.round() as i32);
        if x < left || x > right || y < top || y > bottom {
            continue;
        }
        if dimmed == 0.0 {
            root.draw(&Circle::new((x, y), RADIUS, RGBColor(110, 110, 110).stroke_width(2)))?;
            continue;
        }
        root.draw(&Circle::new((x, y), RADIUS, WHITE.filled()))?;
        root.draw(&Circle::new((x, y), RADIUS, BLACK.stroke_width(2)))?;
        root.draw(&PathElement::new(vec![(x - 5, y - 5), (x + 5, y + 5)], BLACK.stroke_width(1)))?;
        root.draw(&PathElement::new(vec![(x - 5, y + 5), (x + 5, y - 5)], BLACK.stroke_width(1)))?;
        if dimmed != 1.0 {
            let style = ("sans-serif", 12).into_font().color(&BLACK).pos(Pos::new(HPos::Left, VPos::Center));
            root.draw(&Text::new(format!("{:.0} %", dimmed * 100.0), (x + RADIUS + 3, y), style))?;
        }
    }
    Ok(())
}

/// The section's segments, clipped to the plot.
pub fn draw_section(root: &Area, frame: &Frame, layout: &Layout, section: &[[DVec3; 2]]) -> Drawn {
    let [left, top, right, bottom] = layout.plot.map(f64::from);
    let colour = RGBColor(40, 40, 40).stroke_width(2);
    for [a, b] in section {
        let (a, b) = (layout.pixel(frame.plan(*a)), layout.pixel(frame.plan(*b)));
        if let Some((a, b)) = clip(a, b, DVec2::new(left, top), DVec2::new(right, bottom)) {
            let ends = [a, b].map(|q| (q.x.round() as i32, q.y.round() as i32));
            root.draw(&PathElement::new(ends.to_vec(), colour))?;
        }
    }
    Ok(())
}

/// The part of the segment `a b` inside the rectangle `[low, high]` (Liang–Barsky).
fn clip(a: DVec2, b: DVec2, low: DVec2, high: DVec2) -> Option<(DVec2, DVec2)> {
    let d = b - a;
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (p, q) in [(-d.x, a.x - low.x), (d.x, high.x - a.x), (-d.y, a.y - low.y), (d.y, high.y - a.y)] {
        if p == 0.0 {
            if q < 0.0 {
                return None;
            }
        } else if p < 0.0 {
            t0 = t0.max(q / p);
        } else {
            t1 = t1.min(q / p);
        }
    }
    (t0 <= t1).then(|| (a + d * t0, a + d * t1))
}
