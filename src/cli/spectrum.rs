//! `ugo norms --spectrum N`: the table of the leading eigenvalues of `K`, the measured
//! convergence rates against the ones the spectrum predicts (`study::rates`), and the
//! spectrum plot beside the HDF5 file.

use anyhow::Result;
use std::path::{Path, PathBuf};
use ugo::io::{RateLine, Run, spectrum_plot};
use ugo::solve::Spectrum;
use ugo::study::rates;

pub fn report(spectrum: &Spectrum, runs: &[Run], output: &Path, name: &str) -> Result<()> {
    let state = if spectrum.converged { "converged" } else { "NOT converged" };
    println!(
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
    println!("    {:>3} {:>16} {:>16} {:>12} {:>10} {:>12}", "j", "Re λ", "Im λ", "|λ|", "|λ/λ₁|", "‖Kx − λx‖");
    for (j, p) in spectrum.pairs.iter().enumerate() {
        let m = p.magnitude();
        println!(
            "    {:>3} {:>16.10} {:>16.10} {m:>12.8} {:>10.6} {:>12.2e}",
            j + 1,
            p.re,
            p.im,
            m / first,
            p.residual
        );
    }
    let rates = rates(spectrum, runs);
    println!("    rate per product with K   measured    predicted");
    for r in &rates {
        let basis = match r.method {
            ugo::solve::Method::Neumann => "|λ₁|",
            ugo::solve::Method::Gmres { .. } => "|λ₂|",
            _ => "",
        };
        println!("      {:<22} {:>9.5} {:>12.5} {basis}", r.method.name(), r.measured, r.predicted);
    }
    let lines: Vec<RateLine> = rates
        .iter()
        .map(|r| RateLine {
            label: format!("{}: {:.4} per product", r.method.name(), r.predicted),
            start: (r.start.0 as f64, r.start.1),
            end: r.end as f64,
            rate: r.predicted,
        })
        .collect();
    let plot = PathBuf::from(format!("{}-spectrum.png", output.with_extension("").display()));
    spectrum_plot(
        &plot,
        &format!("{name}: the spectrum of K and the convergence it predicts"),
        spectrum,
        runs,
        &lines,
    )?;
    println!("  spectrum plot      {}", plot.display());
    Ok(())
}
