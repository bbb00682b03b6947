//! The plot of `ugo compare --bases`: the relative L² error of each factored angular
//! basis against its unknowns, one line per kind of basis (log–log).

use super::IoError;
use plotters::prelude::*;
use std::path::Path;

/// Draws `(basis name, unknowns, relative L² error)` rows to the PNG `path`.
pub fn basis_plot(path: &Path, title: &str, rows: &[(String, usize, f64)]) -> Result<(), IoError> {
    super::atomic_png(path, |png| draw(png, title, rows).map_err(|e| e.to_string()))
}

/// Relative L² error against unknowns per patch, one line per kind of basis.
fn draw(path: &Path, title: &str, rows: &[(String, usize, f64)]) -> Result<(), Box<dyn std::error::Error>> {
    super::register_font();
    let root = BitMapBackend::new(path, (900, 600)).into_drawing_area();
    root.fill(&WHITE)?;
    let series = |prefix: &str| -> Vec<(f64, f64)> {
        rows.iter().filter(|r| r.0.starts_with(prefix)).map(|r| (r.1 as f64, r.2.max(1e-16))).collect()
    };
    let all: Vec<(f64, f64)> = [series("sh"), series("svd")].concat();
    if all.is_empty() {
        return Ok(());
    }
    let x_max = all.iter().map(|p| p.0).fold(1.0, f64::max) * 1.3;
    let x_min = all.iter().map(|p| p.0).fold(f64::INFINITY, f64::min) / 1.3;
    let y_min = all.iter().map(|p| p.1).fold(f64::INFINITY, f64::min) / 3.0;
    let y_max = all.iter().map(|p| p.1).fold(0.0, f64::max) * 3.0;
    let mut chart = ChartBuilder::on(&root)
        .caption(title, ("sans-serif", 20))
        .margin(20)
        .x_label_area_size(50)
        .y_label_area_size(80)
        .build_cartesian_2d((x_min..x_max).log_scale(), (y_min..y_max).log_scale())?;
    chart
        .configure_mesh()
        .x_desc("unknowns N·M")
        .y_desc("relative L² error of L")
        .y_label_formatter(&|v| format!("{v:.0e}"))
        .label_style(("sans-serif", 15))
        .draw()?;
    for (index, (prefix, label)) in [("sh", "hemispherical harmonics"), ("svd", "truncated SVD")].iter().enumerate() {
        let color = Palette99::pick(index).to_rgba();
        let points = series(prefix);
        chart.draw_series(points.iter().map(|&p| Circle::new(p, 5, color.filled())))?;
        chart
            .draw_series(LineSeries::new(points, color.stroke_width(3)))?
            .label(*label)
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 24, y)], color.stroke_width(3)));
    }
    chart.configure_series_labels().background_style(WHITE.mix(0.85)).border_style(BLACK).draw()?;
    root.present()?;
    Ok(())
}
