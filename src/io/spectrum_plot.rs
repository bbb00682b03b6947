//! The spectrum plot (PNG, plotters) of `ugo norms --spectrum N`: the leading eigenvalues
//! of `K` in the complex plane, and beside them every run's residual against products
//! with `K`, with the rate the spectrum predicts for it drawn dashed from the start of its
//! tail (`study::rates`), and how fast the ratio of successive residuals of successive
//! approximation settles on `|λ₁|` against the gap: `|λ₂/λ₁|ⁿ` in general, `|λ₂/λ₁|²ⁿ`
//! when the eigenvectors are orthogonal (the first-order cross term vanishes).

use super::IoError;
use crate::io::Run;
use crate::solve::Spectrum;
use plotters::prelude::*;
use std::path::Path;

/// A predicted rate: `r(a) = r₀ · rate^(a − a₀)` from `start = (a₀, r₀)` to `a = end`.
pub struct RateLine {
    /// Index of the run it predicts (its colour).
    pub run: usize,
    /// Dotted rather than dashed (a second prediction for the same run).
    pub dotted: bool,
    /// The legend's text.
    pub label: String,
    /// `(a₀, r₀)`: products with `K` and residual where the line starts.
    pub start: (f64, f64),
    /// Products with `K` where it ends.
    pub end: f64,
    /// The contraction per product with `K`.
    pub rate: f64,
}

type Area<'a> = DrawingArea<BitMapBackend<'a>, plotters::coord::Shift>;

/// Writes the two-panel spectrum plot to `path`.
pub fn spectrum_plot(
    path: &Path,
    title: &str,
    spectrum: &Spectrum,
    runs: &[Run],
    lines: &[RateLine],
) -> Result<(), IoError> {
    super::atomic_png(path, |png| {
        super::plot::register_font();
        let root = BitMapBackend::new(png, (1950, 640)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| e.to_string())?;
        let (top, body) = root.split_vertically(50);
        top.titled(title, ("sans-serif", 24)).map_err(|e| e.to_string())?;
        let (left, rest) = body.split_horizontally(560);
        let (middle, right) = rest.split_horizontally(800);
        eigenvalues(&left, spectrum).map_err(|e| e.to_string())?;
        histories(&middle, runs, lines).map_err(|e| e.to_string())?;
        if let Some(neumann) = runs.iter().find(|r| r.method == crate::solve::Method::Neumann) {
            settling(&right, spectrum, neumann).map_err(|e| e.to_string())?;
        }
        root.present().map_err(|e| e.to_string())
    })
}

fn eigenvalues(area: &Area, spectrum: &Spectrum) -> Result<(), Box<dyn std::error::Error>> {
    let rho = spectrum.pairs.first().map_or(1.0, |p| p.magnitude()).max(1e-12) * 1.1;
    let mut chart = ChartBuilder::on(area)
        .margin(20)
        .x_label_area_size(50)
        .y_label_area_size(70)
        .caption(format!("{} eigenvalues of K of largest |λ|", spectrum.pairs.len()), ("sans-serif", 18))
        .build_cartesian_2d(-rho..rho, -rho..rho)?;
    chart
        .configure_mesh()
        .x_desc("Re λ")
        .y_desc("Im λ")
        .label_style(("sans-serif", 15))
        .axis_desc_style(("sans-serif", 17))
        .draw()?;
    let circle: Vec<(f64, f64)> = (0..=200)
        .map(|t| std::f64::consts::TAU * t as f64 / 200.0)
        .map(|t| (rho / 1.1 * t.cos(), rho / 1.1 * t.sin()))
        .collect();
    chart.draw_series(LineSeries::new(circle, BLACK.mix(0.3)))?.label("|λ| = ρ(K)");
    let red = RGBColor(200, 30, 30);
    chart.draw_series(spectrum.pairs.iter().map(|p| Circle::new((p.re, p.im), 5, red.filled())))?;
    for (j, p) in spectrum.pairs.iter().enumerate().take(4) {
        chart.draw_series(std::iter::once(Text::new(
            format!("λ{}", j + 1),
            (p.re, p.im + rho * 0.04),
            ("sans-serif", 15),
        )))?;
    }
    Ok(())
}

type LogChart<'a, 'b> =
    ChartContext<'b, BitMapBackend<'a>, Cartesian2d<plotters::coord::types::RangedCoordf64, LogCoord<f64>>>;

/// A panel with a linear x axis from 0 to `x_max` and a logarithmic y axis over `y`, its
/// caption and x description in `captions`, its mesh drawn.
fn log_chart<'a, 'b>(
    area: &'b Area<'a>,
    [caption, x_desc]: [&str; 2],
    y_desc: &str,
    x_max: f64,
    (y_min, y_max): (f64, f64),
) -> Result<LogChart<'a, 'b>, Box<dyn std::error::Error>> {
    let mut chart = ChartBuilder::on(area)
        .margin(20)
        .x_label_area_size(50)
        .y_label_area_size(80)
        .caption(caption, ("sans-serif", 18))
        .build_cartesian_2d(0.0..x_max, (y_min..y_max).log_scale())?;
    chart
        .configure_mesh()
        .x_desc(x_desc)
        .y_desc(y_desc)
        .y_label_formatter(&|v| format!("{v:.0e}"))
        .label_style(("sans-serif", 15))
        .axis_desc_style(("sans-serif", 17))
        .draw()?;
    Ok(chart)
}

fn histories(area: &Area, runs: &[Run], lines: &[RateLine]) -> Result<(), Box<dyn std::error::Error>> {
    let points = |r: &Run| -> Vec<(f64, f64)> {
        let i = &r.info;
        i.application_history.iter().zip(&i.residual_history).map(|(&a, &x)| (a as f64, x.max(1e-17))).collect()
    };
    let all: Vec<(f64, f64)> = runs.iter().flat_map(points).collect();
    let x_max = all.iter().map(|p| p.0).fold(1.0, f64::max) * 1.05;
    let y_min = all.iter().map(|p| p.1).fold(1.0, f64::min) / 3.0;
    let y_max = all.iter().map(|p| p.1).fold(y_min * 10.0, f64::max) * 3.0;
    let captions = ["measured residuals (solid) and the rates the spectrum predicts (dashed)", "products with K"];
    let mut chart = log_chart(area, captions, "relative residual ‖L0 + Kx − x‖ / ‖L0‖", x_max, (y_min, y_max))?;
    for (index, run) in runs.iter().enumerate() {
        let color = Palette99::pick(index).to_rgba();
        chart
            .draw_series(LineSeries::new(points(run), color.stroke_width(3)))?
            .label(run.method.name())
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 24, y)], color.stroke_width(3)));
    }
    for line in lines.iter().filter(|l| l.rate.is_finite() && l.rate > 0.0) {
        let color = Palette99::pick(line.run).to_rgba();
        let (dash, gap) = if line.dotted { (2, 5) } else { (8, 6) };
        let dashes = decay(line.start, line.end, line.rate, y_min);
        chart
            .draw_series(DashedLineSeries::new(dashes, dash, gap, color.stroke_width(2)))?
            .label(line.label.clone())
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 10, y)], color.stroke_width(2)));
    }
    legend(&mut chart)
}

/// `| ‖r_{n+1}‖/‖r_n‖ − |λ₁| |` of successive approximation against `n`, with `|λ₂/λ₁|ⁿ`
/// through its first point.
fn settling(area: &Area, spectrum: &Spectrum, run: &Run) -> Result<(), Box<dyn std::error::Error>> {
    let (Some(first), Some(second)) = (spectrum.pairs.first(), spectrum.pairs.get(1)) else { return Ok(()) };
    let (rho, gap) = (first.magnitude(), second.magnitude() / first.magnitude());
    let r = &run.info.residual_history;
    let deviation: Vec<(f64, f64)> = (1..r.len())
        .filter(|&n| r[n - 1] > 0.0 && r[n] > 1e-14)
        .map(|n| (n as f64, (r[n] / r[n - 1] - rho).abs()))
        .filter(|p| p.1 > 0.0)
        .collect();
    let Some(&(n0, d0)) = deviation.first() else { return Ok(()) };
    let x_max = deviation.iter().map(|p| p.0).fold(1.0, f64::max) + 1.0;
    let y_min = deviation.iter().map(|p| p.1).fold(d0, f64::min).max(1e-16) / 3.0;
    let y_max = deviation.iter().map(|p| p.1).fold(d0, f64::max) * 3.0;
    let captions = ["successive approximation: the ratio settles on |λ₁|", "iteration n"];
    let mut chart = log_chart(area, captions, "| ‖r_n‖/‖r_(n−1)‖ − |λ₁| |", x_max, (y_min, y_max))?;
    let color = Palette99::pick(0).to_rgba();
    chart
        .draw_series(LineSeries::new(deviation.clone(), color.stroke_width(3)))?
        .label("measured")
        .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 24, y)], color.stroke_width(3)));
    let black = BLACK.to_rgba();
    let predicted = decay((n0, d0), x_max - 1.0, gap, y_min);
    chart
        .draw_series(DashedLineSeries::new(predicted, 8, 6, black.stroke_width(2)))?
        .label(format!("|λ₂/λ₁|ⁿ = {gap:.4}ⁿ"))
        .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 10, y)], black.stroke_width(2)));
    let squared = decay((n0, d0), x_max - 1.0, gap * gap, y_min);
    chart
        .draw_series(DashedLineSeries::new(squared, 2, 5, black.stroke_width(2)))?
        .label("|λ₂/λ₁|²ⁿ (orthogonal eigenvectors)")
        .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 4, y)], black.stroke_width(2)));
    legend(&mut chart)
}

/// `y0 · rateˣ⁻ˣ⁰` from `(x0, y0)` to `x1` at 61 points, floored at `y_min` (a dashed line).
fn decay((x0, y0): (f64, f64), x1: f64, rate: f64, y_min: f64) -> Vec<(f64, f64)> {
    (0..=60).map(|t| x0 + (x1 - x0) * t as f64 / 60.0).map(|x| (x, (y0 * rate.powf(x - x0)).max(y_min))).collect()
}

/// The series' legend, upper right.
fn legend<'a: 'b, 'b>(chart: &mut LogChart<'a, 'b>) -> Result<(), Box<dyn std::error::Error>> {
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperRight)
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .label_font(("sans-serif", 15))
        .draw()?;
    Ok(())
}
