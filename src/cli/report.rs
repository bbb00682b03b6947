//! `ugo report OUT.h5 [-o PAGE.html]`: the HTML report of a solved case
//! (`ugo::io::write_report`, `docs/report.md`), by default `OUT.html` beside the file.

use super::check_writable;
use anyhow::Result;
use std::path::{Path, PathBuf};

pub fn run(solution: &Path, output: Option<PathBuf>) -> Result<()> {
    let output = output.unwrap_or_else(|| solution.with_extension("html"));
    check_writable(&output)?;
    ugo::io::write_report(solution, &output)?;
    say!("written {}", output.display());
    Ok(())
}
