//! `ugo norms --spectrum N`: the table of the leading eigenvalues of `K`, the measured
//! convergence rates against the ones the spectrum predicts (`study::rates`), and the
//! spectrum plot beside the HDF5 file.

use anyhow::Result;
use std::path::Path;
use ugo::io::{RateLine, Run, spectrum_plot};
use ugo::solve::Spectrum;
use ugo::study::rates;

pub fn report(spectrum: &Spectrum, runs: &[Run], output: &Path, name: &str) -> Result<()> {
    let state = if spectrum.converged { "converged" } else { "NOT converged" };
    say!(
        "  spectrum of K      {} eigenvalues, {} restarts, {} products with K, {:.3} s ({state} to {:.0e} of |λ₁|)",
        spectrum.pairs.len(),
        spectrum.restarts,
        spectrum.applications,
        spectrum.seconds,
        spectrum.tolerance
    );
    if !spectrum.converged {
        eprintln!("ugo: warning: Arnoldi did not converge: the eigen-residuals below say how far each pair is");
    }
    let first = spectrum.pairs.first().map_or(f64::NAN, |p| p.magnitude());
    say!("    {:>3} {:>16} {:>16} {:>12} {:>10} {:>12}", "j", "Re λ", "Im λ", "|λ|", "|λ/λ₁|", "‖Kx − λx‖");
    for (j, p) in spectrum.pairs.iter().enumerate() {
        let m = p.magnitude();
        say!("    {:>3} {:>16.10} {:>16.10} {m:>12.8} {:>10.6} {:>12.2e}", j + 1, p.re, p.im, m / first, p.residual);
    }
    let rates = rates(spectrum, runs);
    say!("    rate per product with K   measured    predicted");
    for r in &rates {
        let basis = match r.method {
            ugo::solve::Method::Neumann => "|λ₁|".to_string(),
            ugo::solve::Method::Gmres { .. } => format!("|λ₂|; Chebyshev on [1 − λ₁, 1 − λ_min]: {:.5}", r.interval),
            _ => String::new(),
        };
        say!("      {:<22} {:>9.5} {:>12.5} {basis}", r.method.name(), r.measured, r.predicted);
    }
    let line = |run: usize, r: &ugo::study::Rate, rate: f64, what: &str| RateLine {
        run,
        dotted: what == "Chebyshev",
        label: format!("{} {what}: {rate:.4}", r.method.name()),
        start: (r.start.0 as f64, r.start.1),
        end: r.end as f64,
        rate,
    };
    let mut lines: Vec<RateLine> = Vec::new();
    for (run, r) in rates.iter().enumerate() {
        let what = if matches!(r.method, ugo::solve::Method::Neumann) { "|λ₁|" } else { "|λ₂|" };
        lines.push(line(run, r, r.predicted, what));
        if r.interval.is_finite() {
            lines.push(line(run, r, r.interval, "Chebyshev"));
        }
    }
    let plot = super::beside(output, "-spectrum.png");
    spectrum_plot(
        &plot,
        &format!("{name}: the spectrum of K and the convergence it predicts"),
        spectrum,
        runs,
        &lines,
    )?;
    say!("  spectrum plot      {}", plot.display());
    Ok(())
}
