//! Convergence plots (PNG, plotters): relative residual against iterations, kernel
//! applications and wall time, log scale, one line per method (a dot marks where it
//! stopped, so a direct solve shows as one dot), with a legend.

use super::IoError;
use crate::io::Run;
use plotters::prelude::*;
use std::path::Path;

/// The horizontal coordinate of a run's `i`-th record.
type Abscissa = dyn Fn(&Run, usize) -> f64;

const FONT: &[u8] = include_bytes!("../../assets/DejaVuSans.ttf");

/// Writes the three-panel convergence plot of `runs` to `path` (PNG).
pub fn convergence_plot(path: &Path, title: &str, runs: &[Run]) -> Result<(), IoError> {
    super::atomic_png(path, |png| draw_plot(png, title, runs))
}

fn draw_plot(path: &Path, title: &str, runs: &[Run]) -> Result<(), String> {
    register_font();
    let root = BitMapBackend::new(path, (1800, 640)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| e.to_string())?;
    let (top, body) = root.split_vertically(50);
    top.titled(title, ("sans-serif", 26)).map_err(|e| e.to_string())?;
    let panels = body.split_evenly((1, 3));
    let axes: [(&str, &Abscissa); 3] = [
        ("iterations", &|_, i| i as f64),
        ("kernel applications", &|r, i| r.info.application_history[i] as f64),
        ("wall time, s", &|r, i| r.info.time_history[i]),
    ];
    for (panel, (label, x_of)) in panels.iter().zip(axes) {
        draw_panel(panel, label, x_of, runs).map_err(|e| e.to_string())?;
    }
    root.present().map_err(|e| e.to_string())
}

fn draw_panel(
    area: &DrawingArea<BitMapBackend, plotters::coord::Shift>,
    label: &str,
    x_of: &dyn Fn(&Run, usize) -> f64,
    runs: &[Run],
) -> Result<(), Box<dyn std::error::Error>> {
    let points = |r: &Run| -> Vec<(f64, f64)> {
        (0..r.info.residual_history.len()).map(|i| (x_of(r, i), r.info.residual_history[i].max(1e-17))).collect()
    };
    let all: Vec<(f64, f64)> = runs.iter().flat_map(points).collect();
    let x_max = all.iter().map(|p| p.0).fold(0.0, f64::max).max(1e-3) * 1.05;
    let y_min = all.iter().map(|p| p.1).fold(f64::INFINITY, f64::min).max(1e-17) / 3.0;
    let y_max = all.iter().map(|p| p.1).fold(0.0, f64::max).max(y_min * 10.0) * 3.0;
    let mut chart = ChartBuilder::on(area)
        .margin(20)
        .x_label_area_size(50)
        .y_label_area_size(80)
        .build_cartesian_2d(0.0..x_max, (y_min..y_max).log_scale())?;
    chart
        .configure_mesh()
        .x_desc(label)
        .y_desc("relative residual ‖L0 + Kx − x‖ / ‖L0‖")
        .y_label_formatter(&|v| format!("{v:.0e}"))
        .label_style(("sans-serif", 16))
        .axis_desc_style(("sans-serif", 18))
        .draw()?;
    for (index, run) in runs.iter().enumerate() {
        let color = Palette99::pick(index).to_rgba();
        let last = points(run).last().copied();
        chart.draw_series(last.map(|p| Circle::new(p, 6, color.filled())))?;
        chart
            .draw_series(LineSeries::new(points(run), color.stroke_width(3)))?
            .label(run.method.name())
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 24, y)], color.stroke_width(3)));
    }
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperRight)
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .label_font(("sans-serif", 16))
        .draw()?;
    Ok(())
}

/// Makes the bundled DejaVu Sans the "sans-serif" font of plotters (once).
pub fn register_font() {
    static ONCE: std::sync::Once = std::sync::Once::new();
    ONCE.call_once(|| {
        let _ = plotters::style::register_font("sans-serif", FontStyle::Normal, FONT);
    });
}
