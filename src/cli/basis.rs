//! The angular-basis options (`--basis sh --lmax L`, `--basis svd --rank R`) and
//! `ugo compare --bases …` (`study::compare_bases`) printed as a table and drawn as a plot
//! (`docs/design.md` §4).

use super::options::{BasisArg, Discretize, basis};
use super::{Bars, bytes, load};
use anyhow::{Result, bail};
use std::path::Path;
use ugo::basis::Basis;
use ugo::io::basis_plot;
use ugo::solve::{Method, SolveParams};
use ugo::study::{BasisStudy, compare_bases};

/// `--basis`, `--lmax`, `--rank`.
#[derive(Debug, Clone, clap::Args)]
pub struct BasisOptions {
    /// Solve for the coefficients of an angular basis: `sh` (hemispherical harmonics,
    /// with --lmax) or `svd` (truncated SVD of each material block, with --rank).
    #[arg(long, value_parser = basis)]
    basis: Option<BasisArg>,
    /// Highest harmonic degree of `--basis sh`: (lmax+1)² coefficients per patch.
    #[arg(long, allow_negative_numbers = true, requires = "basis")]
    lmax: Option<usize>,
    /// Rank of `--basis svd`: coefficients per patch.
    #[arg(long, allow_negative_numbers = true, requires = "basis")]
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
    let scene = load(case, d)?;
    super::check_writable(plot)?;
    let BasisStudy { model, rows } = compare_bases(&scene, &bases, method, params, &Bars::default())?;
    let n = model.mesh.len();
    say!(
        "ugo: {} — {} patches, {} cells, {} by {}; errors against the full angular solution",
        scene.name,
        n,
        model.kernel.cells(),
        method.name(),
        if params.tolerance > 0.0 { format!("tolerance {:.0e}", params.tolerance) } else { String::new() }
    );
    say!(
        "  {:<8} {:>10} {:>12} {:>9} {:>6} {:>11} {:>11} {:>13}",
        "basis",
        "unknowns",
        "assembled",
        "time s",
        "iter.",
        "rel. L² err",
        "max err",
        "full residual"
    );
    for r in &rows {
        say!(
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
    let points: Vec<(String, usize, f64)> = rows.iter().map(|r| (r.name.clone(), r.unknowns, r.error)).collect();
    basis_plot(plot, &format!("{}: factored bases against the full angular solution", scene.name), &points)?;
    say!("  plot     {}", plot.display());
    Ok(())
}
