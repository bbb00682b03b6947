//! `ugo export FILE.h5 --format mtx|petsc -o DIR` (issue 15, docs/kernel-file.md): the
//! kernel saved in a solution file (`ugo solve --save-kernel`) written as `K`, `I − K` and
//! `L0` for scipy, PETSc and other programs.

use super::bytes;
use anyhow::{Context, Result, bail};
use std::path::{Path, PathBuf};
use ugo::io::{Format, export, read_kernel};

/// `--format`.
#[derive(clap::ValueEnum, Clone, Copy, Debug)]
pub enum FormatArg {
    /// Matrix Market text (scipy.io.mmread).
    Mtx,
    /// PETSc binary (MatLoad, VecLoad).
    Petsc,
}

impl From<FormatArg> for Format {
    fn from(f: FormatArg) -> Format {
        match f {
            FormatArg::Mtx => Format::MatrixMarket,
            FormatArg::Petsc => Format::Petsc,
        }
    }
}

/// The arguments of `ugo export`.
#[derive(clap::Args, Debug)]
pub struct ExportOptions {
    /// A solution file with a saved kernel (`ugo solve CASE --save-kernel`).
    pub solution: PathBuf,
    /// File format of K, I − K and L0.
    #[arg(long, value_enum)]
    pub format: FormatArg,
    /// Folder for K.<ext>, I-K.<ext> and L0.<ext> (it must exist).
    #[arg(short, long, default_value = ".")]
    pub output: PathBuf,
    /// Largest explicit product K = B·G allowed, GiB (default: half of the least of the machine's RAM, the control group's limit and `ulimit -v`).
    #[arg(long, allow_negative_numbers = true)]
    pub memory_limit: Option<f64>,
}

pub fn run(o: &ExportOptions) -> Result<()> {
    if !o.output.is_dir() {
        bail!("cannot write into {}: not a folder", o.output.display());
    }
    let limit = match o.memory_limit {
        Some(gib) if !(gib.is_finite() && gib > 0.0) => {
            bail!("--memory-limit must be a positive number of GiB, got {gib}")
        }
        Some(gib) => (gib * (1u64 << 30) as f64) as u64,
        None => ugo::kernel::memory::default_limit(),
    };
    let stored = read_kernel(&o.solution)?;
    let paths = export(&stored, o.format.into(), &o.output, limit)
        .with_context(|| format!("exporting the kernel of {}", o.solution.display()))?;
    let n = stored.kernel.g.rows();
    say!("ugo: the kernel of {} ({n} unknowns)", o.solution.display());
    for path in &paths {
        say!("  {:<40} {}", path.display(), size(path));
    }
    Ok(())
}

fn size(path: &Path) -> String {
    std::fs::metadata(path).map_or_else(|_| "?".to_string(), |m| bytes(m.len() as f64))
}
