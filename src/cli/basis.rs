//! The angular-basis options (`--basis sh --lmax L`, `--basis svd --rank R`) and
//! `ugo compare --bases …`: the same case solved in the full cell basis and in several
//! factored bases, with the error of each against the full angular solution, its
//! unknowns, memory and time, as a table and a plot (`design.md` §4).

use super::options::{BasisArg, Discretize, basis};
use super::{bar, bytes, load};
use anyhow::{Result, bail};
use plotters::prelude::*;
use std::path::Path;
use std::time::Instant;
use ugo::basis::{Basis, Factorization, Reduced};
use ugo::kernel::Factored;
use ugo::model::Model;
use ugo::solve::{Method, SolveParams, System, relative_residual, solve};

/// `--basis`, `--lmax`, `--rank`.
#[derive(Debug, Clone, clap::Args)]
pub struct BasisOptions {
    /// Solve for the coefficients of an angular basis: `sh` (hemispherical harmonics,
    /// with --lmax) or `svd` (truncated SVD of each material block, with --rank).
    #[arg(long, value_parser = basis)]
    basis: Option<BasisArg>,
    /// Highest harmonic degree of `--basis sh`: (lmax+1)² coefficients per patch.
    #[arg(long, requires = "basis")]
    lmax: Option<usize>,
    /// Rank of `--basis svd`: coefficients per patch.
    #[arg(long, requires = "basis")]
    rank: Option<usize>,
}

impl BasisOptions {
    pub fn choice(&self) -> Result<Option<Basis>> {
        Ok(match (self.basis, self.lmax, self.rank) {
            (None, _, _) => None,
            (Some(BasisArg::Sh), Some(lmax), None) => Some(Basis::Sh { lmax }),
            (Some(BasisArg::Svd), None, Some(rank)) if rank >= 1 => Some(Basis::Svd { rank }),
            (Some(BasisArg::Sh), _, _) => bail!("--basis sh takes --lmax L (and no --rank)"),
            (Some(BasisArg::Svd), _, _) => bail!("--basis svd takes --rank R ≥ 1 (and no --lmax)"),
        })
    }
}

/// One line of the study.
struct Row {
    name: String,
    unknowns: usize,
    /// Bytes of the assembled operator (the explicit `B·G` or `Φᵀ G Ψ`).
    memory: f64,
    seconds: f64,
    iterations: usize,
    error: f64,
    max_error: f64,
    residual: f64,
}

/// `ugo compare CASE --bases full,sh:2,svd:8 …`.
pub fn study(
    case: &Path,
    d: &Discretize,
    names: &[String],
    method: Method,
    params: SolveParams,
    plot: &Path,
) -> Result<()> {
    let bases: Vec<Option<Basis>> = names
        .iter()
        .map(|n| match n.as_str() {
            "full" => Ok(None),
            other => Basis::parse(other)
                .map(Some)
                .ok_or_else(|| anyhow::anyhow!("unknown basis \"{other}\"; use full, sh:L (L ≥ 0) or svd:R (R ≥ 1)")),
        })
        .collect::<Result<_>>()?;
    let (scene, options) = load(case, d)?;
    let assembly = bar(0, "assembly");
    let model = Model::build(&scene, &options, &|total| assembly.set_length(total), &|done| assembly.inc(done))?;
    assembly.finish_and_clear();
    let factored = Factored::new(&model.kernel);
    let start = Instant::now();
    let system = System::of(&model.kernel, &factored, None, &[], &model.l0);
    let (reference, info) =
        solve(method, &system, &SolveParams { memory_limit: options.memory_limit, ..params }, &mut |_, _| {})?;
    let full_seconds = start.elapsed().as_secs_f64();
    let norm = |v: &mut dyn Iterator<Item = f64>| v.map(|e| e * e).sum::<f64>().sqrt();
    let scale = norm(&mut reference.iter().copied());
    let peak = reference.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let n = model.mesh.len();
    let mut rows = Vec::new();
    for basis in &bases {
        let row = match basis {
            None => Row {
                name: "full".into(),
                unknowns: reference.len(),
                memory: model.kernel.explicit_nonzeros() * 16.0,
                seconds: full_seconds,
                iterations: info.iterations,
                error: 0.0,
                max_error: 0.0,
                residual: relative_residual(&factored, &model.l0, &reference),
            },
            Some(b) => {
                let start = Instant::now();
                let factors = Factorization::new(*b, &model.kernel.blocks, &model.kernel.directions)?;
                let reduced = Reduced::new(&model.kernel, &factors);
                let source = reduced.source(&model.l0);
                let system = System { operator: &reduced, explicit: None, areas: &[], l0: &source };
                let (c, info) = solve(
                    method,
                    &system,
                    &SolveParams { memory_limit: options.memory_limit, ..params },
                    &mut |_, _| {},
                )?;
                let x = reduced.field(&model.l0, &c);
                let seconds = start.elapsed().as_secs_f64();
                let diff: Vec<f64> = x.iter().zip(&reference).map(|(a, r)| a - r).collect();
                Row {
                    name: b.name(),
                    unknowns: n * factors.m,
                    memory: reduced.explicit_nonzeros() * 16.0,
                    seconds,
                    iterations: info.iterations,
                    error: norm(&mut diff.iter().copied()) / scale,
                    max_error: diff.iter().fold(0.0f64, |m, v| m.max(v.abs())) / peak,
                    residual: relative_residual(&factored, &model.l0, &x),
                }
            }
        };
        rows.push(row);
    }
    println!(
        "ugo: {} — {} patches, {} cells, {} by {}; errors against the full angular solution",
        scene.name,
        n,
        model.kernel.cells(),
        method.name(),
        if params.tolerance > 0.0 { format!("tolerance {:.0e}", params.tolerance) } else { String::new() }
    );
    println!(
        "  {:<8} {:>10} {:>12} {:>9} {:>6} {:>11} {:>11} {:>13}",
        "basis", "unknowns", "assembled", "time s", "iter.", "rel. L² err", "max err", "full residual"
    );
    for r in &rows {
        println!(
            "  {:<8} {:>10} {:>12} {:>9.3} {:>6} {:>11.3e} {:>11.3e} {:>13.2e}",
            r.name,
            r.unknowns,
            bytes(r.memory),
            r.seconds,
            r.iterations,
            r.error,
            r.max_error,
            r.residual
        );
    }
    draw(plot, &format!("{}: factored bases against the full angular solution", scene.name), &rows)
        .map_err(|e| anyhow::anyhow!("writing {}: {e}", plot.display()))?;
    println!("  plot     {}", plot.display());
    Ok(())
}

/// Relative L² error against unknowns per patch, one line per kind of basis.
fn draw(path: &Path, title: &str, rows: &[Row]) -> Result<(), Box<dyn std::error::Error>> {
    ugo::io::register_font();
    let root = BitMapBackend::new(path, (900, 600)).into_drawing_area();
    root.fill(&WHITE)?;
    let series = |prefix: &str| -> Vec<(f64, f64)> {
        rows.iter().filter(|r| r.name.starts_with(prefix)).map(|r| (r.unknowns as f64, r.error.max(1e-16))).collect()
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
