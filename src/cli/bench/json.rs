//! The figures of `ugo bench` written as JSON (`--json`).

use super::options::BenchOptions;
use anyhow::Result;

/// Writes `report` to `--json`, if given.
pub fn write_json(o: &BenchOptions, report: &serde_json::Value) -> Result<()> {
    if let Some(path) = &o.json {
        ugo::io::write_bytes(path, serde_json::to_string_pretty(report)?.as_bytes())?;
        say!("  json                  {}", path.display());
    }
    Ok(())
}
