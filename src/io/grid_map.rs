//! The plan of an illuminance grid (`OUT-<grid>.png`), drawn as a lighting engineer reads
//! one: the grid seen from the side its normal points to (`super::plan`, never mirrored),
//! its cells in false colour with a legend in lx at round values, axes in metres with
//! round ticks, the grid's outline, the luminaires (full, dimmed or off) and the section
//! of the surfaces by the grid's plane (`plan_marks.rs`), the statistics
//! `E_avg`, `E_min`, `E_max`, `U0` in the title, the cells of points left out of them
//! (`readout::obstructed`) hatched in grey and counted in the title, and on request (`[[grid]] map = { … }`)
//! a log scale, the value of every cell and lines of equal illuminance (isolux lines).
//! Under a `[sky]` the same plan shows the daylight factor (or ratio) in %
//! ([`write_daylight_map`], `OUT-<grid>-DF.png`).

use super::IoError;
use super::false_colour::{Scale, bounds, colour, legend, position};
use super::isolines::isolines;
use super::plan::{Axis, Frame, Layout};
use super::plan_marks::{Overlay, draw_lamps, draw_section};
use super::ticks::{log_ticks, round_125, round_top, tick_label, ticks};
use crate::readout::grid::GridReading;
use crate::render::Image;
use crate::scene::MapScale;
use glam::{DVec2, DVec3};
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use std::path::Path;

type Area<'a> = DrawingArea<BitMapBackend<'a>, plotters::coord::Shift>;
type Drawn = Result<(), Box<dyn std::error::Error>>;

/// The plot's longer side, pixels.
const PLOT: f64 = 560.0;
/// Margin left of the plot (vertical ticks), pixels.
const LEFT: i32 = 80;
/// Margin above the plot (title), pixels.
const TOP: i32 = 84;
/// Margin below the plot (horizontal ticks and caption), pixels.
const BOTTOM: i32 = 64;

/// The picture of a grid's plan: its frame, where it lies, and the picture's size.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GridPlan {
    /// The plan's axes.
    pub frame: Frame,
    /// Where the plan lies in the picture.
    pub layout: Layout,
    /// The picture's width and height, pixels.
    pub size: (u32, u32),
}

impl GridPlan {
    /// The plan of `grid`'s rectangle and of the luminaires at `luminaires` that lie
    /// over it or near it (within a tenth of its size).
    pub fn of(grid: &GridReading, luminaires: &[DVec3]) -> GridPlan {
        let frame = Frame::of(&grid.grid);
        let corners = outline(grid).map(|p| frame.plan(p));
        let (low, high) = extent(&corners);
        let near = (high - low).max_element() * 0.1;
        let lamps = luminaires
            .iter()
            .map(|&p| frame.plan(p))
            .filter(|q| q.cmpge(low - DVec2::splat(near)).all() && q.cmple(high + DVec2::splat(near)).all());
        let all: Vec<DVec2> = corners.into_iter().chain(lamps).collect();
        let (low, high) = extent(&all);
        let pad = DVec2::splat((high - low).max_element() * 0.04);
        let layout = Layout::fit(low - pad, high + pad, PLOT, (LEFT, TOP));
        let width = layout.plot[2] + 40 + super::LEGEND_WIDTH as i32;
        let height = (layout.plot[3] + BOTTOM).max(TOP + 300);
        GridPlan { frame, layout, size: (width as u32, height as u32) }
    }
}

fn outline(grid: &GridReading) -> [DVec3; 4] {
    let g = &grid.grid;
    [g.origin, g.origin + g.edge_u, g.origin + g.edge_u + g.edge_v, g.origin + g.edge_v]
}

fn extent(points: &[DVec2]) -> (DVec2, DVec2) {
    let low = points.iter().fold(DVec2::splat(f64::INFINITY), |a, &b| a.min(b));
    let high = points.iter().fold(DVec2::splat(f64::NEG_INFINITY), |a, &b| a.max(b));
    (low, high)
}

/// What a plan shows: one value per point of the grid, its symbol and its unit.
pub(super) struct Shown<'a> {
    values: &'a [f64],
    symbol: &'a str,
    unit: &'a str,
}

impl<'a> Shown<'a> {
    /// The grid's illuminance, lx.
    pub(super) fn illuminance(grid: &'a GridReading) -> Shown<'a> {
        Shown { values: &grid.illuminance, symbol: "E", unit: "lx" }
    }

    /// The daylight factor (`symbol` `"DF"`) or ratio (`"DR"`), %, one value per point.
    pub(super) fn daylight(values: &'a [f64], symbol: &'a str) -> Shown<'a> {
        Shown { values, symbol, unit: "%" }
    }
}

/// Writes the plan of `grid`'s illuminance, with the luminaires and the section of
/// `overlay`, to `path` (PNG).
pub fn write_grid_map(path: &Path, grid: &GridReading, overlay: &Overlay) -> Result<(), IoError> {
    write_map(path, grid, &Shown::illuminance(grid), overlay)
}

/// Writes the plan of the daylight factor (`symbol` `"DF"`) or ratio (`"DR"`) on `grid`, %,
/// one value per point, to `path` (PNG).
pub fn write_daylight_map(
    path: &Path,
    grid: &GridReading,
    values: &[f64],
    symbol: &str,
    overlay: &Overlay,
) -> Result<(), IoError> {
    write_map(path, grid, &Shown::daylight(values, symbol), overlay)
}

fn write_map(path: &Path, grid: &GridReading, shown: &Shown, overlay: &Overlay) -> Result<(), IoError> {
    let png = plan_png(grid, shown, overlay).map_err(|why| IoError::write(path, why))?;
    super::write_bytes(path, &png)
}

/// The plan of `shown` on `grid` as the bytes of a PNG file (the report embeds them).
pub(super) fn plan_png(grid: &GridReading, shown: &Shown, overlay: &Overlay) -> Result<Vec<u8>, String> {
    let plan = GridPlan::of(grid, &overlay.positions());
    let (width, height) = plan.size;
    let mut rgb = vec![0u8; width as usize * height as usize * 3];
    draw(&mut rgb, grid, shown, &plan, overlay).map_err(|e| e.to_string())?;
    let picture = ::image::RgbImage::from_raw(width, height, rgb).ok_or("the plan's pixels do not fill it")?;
    let mut png = std::io::Cursor::new(Vec::new());
    picture.write_to(&mut png, ::image::ImageFormat::Png).map_err(|e| e.to_string())?;
    Ok(png.into_inner())
}

fn draw(rgb: &mut [u8], grid: &GridReading, shown: &Shown, plan: &GridPlan, overlay: &Overlay) -> Drawn {
    super::plot::register_font();
    let root = BitMapBackend::with_buffer(rgb, plan.size).into_drawing_area();
    root.fill(&WHITE)?;
    let style = grid.grid.map;
    let scale = match style.scale {
        MapScale::Linear => Scale::Linear,
        MapScale::Log => Scale::Log,
    };
    let range = scale_range(grid, shown.values, scale);
    title(&root, grid, shown)?;
    cells(&root, grid, shown.values, plan, scale, range)?;
    if style.isolines {
        isolux(&root, grid, shown.values, plan, scale, range)?;
    }
    if style.values {
        values(&root, grid, shown.values, plan)?;
    }
    draw_section(&root, &plan.frame, &plan.layout, overlay.section)?;
    let corners: Vec<(i32, i32)> = outline(grid).iter().map(|&p| pixel(plan, p)).collect();
    root.draw(&PathElement::new([&corners[..], &corners[..1]].concat(), BLACK.stroke_width(2)))?;
    draw_lamps(&root, &plan.frame, &plan.layout, overlay)?;
    axes(&root, plan)?;
    let [_, top, right, _] = plan.layout.plot;
    let bottom = (plan.size.1 as i32 - BOTTOM).max(top + 200);
    legend(&root, (right + 40, top, bottom), scale, range, shown.unit)?;
    root.present()?;
    Ok(())
}

fn pixel(plan: &GridPlan, p: DVec3) -> (i32, i32) {
    let q = plan.layout.pixel(plan.frame.plan(p));
    (q.x.round() as i32, q.y.round() as i32)
}

/// The colour scale: linear from 0 to a round top, or the log scale of the luminance maps.
fn scale_range(grid: &GridReading, values: &[f64], scale: Scale) -> (f64, f64) {
    let max = values.iter().copied().fold(0.0, f64::max);
    match scale {
        Scale::Log => {
            let [nu, nv] = grid.grid.resolution;
            let (lo, hi) = bounds(&Image { width: nu, height: nv, luminance: values.to_vec() }, scale);
            (round_125(lo, false), round_125(hi, true))
        }
        _ if max > 0.0 => (0.0, round_top(0.0, max, 6)),
        _ => (0.0, 1.0),
    }
}

/// Illuminance as text: three significant figures, no exponent for room values.
fn lux(e: f64) -> String {
    match e.abs() {
        m if m >= 100.0 || m == 0.0 => format!("{e:.0}"),
        m if m >= 10.0 => format!("{e:.1}"),
        m if m >= 0.01 => format!("{e:.2}"),
        _ => format!("{e:.1e}"),
    }
}

fn title(root: &Area, grid: &GridReading, shown: &Shown) -> Drawn {
    let g = &grid.grid;
    let st = grid.stats_of(shown.values);
    let n = g.normal;
    let side = match (0..3).find(|&k| n[k].abs() > 1.0 - 1e-9) {
        Some(k) => format!("{}{}", if n[k] > 0.0 { "+" } else { "−" }, ["x", "y", "z"][k]),
        None => format!("({:.3}, {:.3}, {:.3})", n.x, n.y, n.z),
    };
    let [nu, nv] = g.resolution;
    let head = format!("grid \"{}\", {nu} × {nv} points, seen from {side}", g.name);
    let left_out = match grid.left_out() {
        0 => String::new(),
        1 => "   (hatched: 1 point left out)".to_string(),
        n => format!("   (hatched: {n} points left out)"),
    };
    let (x, unit) = (shown.symbol, shown.unit);
    let ratio = if x == "E" { "U0".to_string() } else { format!("{x}_min/{x}_avg") };
    let stats = format!(
        "{x}_avg {} {unit}   {x}_min {} {unit}   {x}_max {} {unit}   {ratio} {:.2}{left_out}",
        lux(st.average),
        lux(st.min),
        lux(st.max),
        st.u0
    );
    root.draw(&Text::new(head, (LEFT, 10), ("sans-serif", 18).into_font().color(&BLACK)))?;
    root.draw(&Text::new(stats, (LEFT, 34), ("sans-serif", 18).into_font().color(&BLACK)))?;
    Ok(())
}

/// The grid's parameters `(a, b) ∈ [0, 1)²` at a plan point, when it lies on the grid.
struct Cells {
    origin: DVec2,
    u: DVec2,
    v: DVec2,
    det: f64,
}

impl Cells {
    fn of(grid: &GridReading, frame: &Frame) -> Cells {
        let g = &grid.grid;
        let origin = frame.plan(g.origin);
        let (u, v) = (frame.plan(g.origin + g.edge_u) - origin, frame.plan(g.origin + g.edge_v) - origin);
        Cells { origin, u, v, det: u.perp_dot(v) }
    }

    fn at(&self, q: DVec2) -> Option<(f64, f64)> {
        let d = q - self.origin;
        let (a, b) = (d.perp_dot(self.v) / self.det, self.u.perp_dot(d) / self.det);
        ((0.0..1.0).contains(&a) && (0.0..1.0).contains(&b)).then_some((a, b))
    }

    /// The lattice point `(i, j)` of the calculation points (cell centres) on the plan.
    fn point(&self, (i, j): (f64, f64), [nu, nv]: [usize; 2]) -> DVec2 {
        self.origin + self.u * (i + 0.5) / nu as f64 + self.v * (j + 0.5) / nv as f64
    }
}

fn cells(root: &Area, grid: &GridReading, shown: &[f64], plan: &GridPlan, scale: Scale, (lo, hi): (f64, f64)) -> Drawn {
    let [nu, nv] = grid.grid.resolution;
    let on = Cells::of(grid, &plan.frame);
    let [left, top, right, bottom] = plan.layout.plot;
    for y in top..bottom {
        for x in left..right {
            let Some((a, b)) = on.at(plan.layout.point(x as f64 + 0.5, y as f64 + 0.5)) else { continue };
            let (i, j) = (((a * nu as f64) as usize).min(nu - 1), ((b * nv as f64) as usize).min(nv - 1));
            let e = shown[j * nu + i];
            let shade = match grid.obstructed[j * nu + i] {
                // grey, hatched along the plan's diagonals
                Some(_) if (x + y).rem_euclid(8) < 2 => RGBColor(110, 110, 110),
                Some(_) => RGBColor(200, 200, 200),
                None => colour(position(e, lo, hi, scale)),
            };
            root.draw_pixel((x, y), &shade)?;
        }
    }
    root.draw(&Rectangle::new([(left, top), (right, bottom)], RGBColor(160, 160, 160)))?;
    Ok(())
}

/// Lines of equal illuminance at the legend's values inside the scale.
fn isolux(
    root: &Area,
    grid: &GridReading,
    shown: &[f64],
    plan: &GridPlan,
    scale: Scale,
    (lo, hi): (f64, f64),
) -> Drawn {
    let levels = match scale {
        Scale::Log => log_ticks(lo, hi, 9),
        _ => ticks(lo, hi, 6),
    };
    let on = Cells::of(grid, &plan.frame);
    let resolution = grid.grid.resolution;
    let ink = RGBColor(30, 30, 30);
    for level in levels.into_iter().filter(|&l| l > lo && l < hi) {
        for segment in isolines(shown, resolution, level) {
            let ends: Vec<(i32, i32)> = segment
                .iter()
                .map(|&p| plan.layout.pixel(on.point(p, resolution)))
                .map(|q| (q.x.round() as i32, q.y.round() as i32))
                .collect();
            root.draw(&PathElement::new(ends, ink.stroke_width(1)))?;
        }
    }
    Ok(())
}

/// Each cell's value at its centre; every k-th cell where the cells are too small for all.
fn values(root: &Area, grid: &GridReading, shown: &[f64], plan: &GridPlan) -> Drawn {
    let [nu, nv] = grid.grid.resolution;
    let on = Cells::of(grid, &plan.frame);
    let widest = shown.iter().map(|&e| lux(e).len()).max().unwrap_or(1) as f64;
    let cell_u = on.u.length() * plan.layout.scale / nu as f64;
    let cell_v = on.v.length() * plan.layout.scale / nv as f64;
    // A label is about 7 px per character and 14 px tall, whichever way the cells run.
    let need = widest * 7.0 + 4.0;
    let (step_u, step_v) = ((need / cell_u).ceil().max(1.0) as usize, (need / cell_v).ceil().max(1.0) as usize);
    let style = ("sans-serif", 12).into_font().color(&BLACK).pos(Pos::new(HPos::Center, VPos::Center));
    for j in (step_v / 2..nv).step_by(step_v) {
        for i in (step_u / 2..nu).step_by(step_u) {
            let q = plan.layout.pixel(on.point((i as f64, j as f64), [nu, nv]));
            let text = lux(shown[j * nu + i]);
            root.draw(&Text::new(text, (q.x.round() as i32, q.y.round() as i32), style.clone()))?;
        }
    }
    Ok(())
}

/// Ticks at round readings along the plot's bottom and left sides, and the captions.
fn axes(root: &Area, plan: &GridPlan) -> Drawn {
    let l = &plan.layout;
    let [left, top, right, bottom] = l.plot;
    let (low, high) = (l.point(left as f64, bottom as f64), l.point(right as f64, top as f64));
    let font = ("sans-serif", 13).into_font().color(&BLACK);
    let along = |axis: &Axis, a: f64, b: f64, pixels: i32| {
        let (r0, r1) = (axis.reading(a), axis.reading(b));
        ticks(r0.min(r1), r0.max(r1), (pixels / 60).max(2) as usize)
    };
    for t in along(&plan.frame.right, low.x, high.x, right - left) {
        let x = l.pixel(DVec2::new(plan.frame.right.reading(t), low.y)).x.round() as i32;
        root.draw(&PathElement::new(vec![(x, bottom), (x, bottom + 5)], BLACK))?;
        let style = font.clone().pos(Pos::new(HPos::Center, VPos::Top));
        root.draw(&Text::new(tick_label(t), (x, bottom + 8), style))?;
    }
    for t in along(&plan.frame.up, low.y, high.y, bottom - top) {
        let y = l.pixel(DVec2::new(low.x, plan.frame.up.reading(t))).y.round() as i32;
        root.draw(&PathElement::new(vec![(left - 5, y), (left, y)], BLACK))?;
        let style = font.clone().pos(Pos::new(HPos::Right, VPos::Center));
        root.draw(&Text::new(tick_label(t), (left - 8, y), style))?;
    }
    let caption = ("sans-serif", 15).into_font().color(&BLACK);
    let centre = (left + right) / 2;
    let style = caption.clone().pos(Pos::new(HPos::Center, VPos::Top));
    root.draw(&Text::new(plan.frame.right.caption(), (centre, bottom + 30), style))?;
    let style = caption.pos(Pos::new(HPos::Left, VPos::Bottom));
    root.draw(&Text::new(plan.frame.up.caption(), (8, top - 6), style))?;
    Ok(())
}
