//! What a command says when a signal stopped its work (`ugo::interrupt`): the files it has
//! not written, and that the previous ones are left as they were.

use std::path::Path;

/// `error` as it is, or, when a signal stopped the work, with the `outputs` not written.
pub fn not_written(error: impl Into<anyhow::Error>, outputs: &[&Path]) -> anyhow::Error {
    let error = error.into();
    if ugo::interrupt::requested(String::new).is_none() {
        return error;
    }
    let names: Vec<String> = outputs.iter().map(|p| p.display().to_string()).collect();
    anyhow::anyhow!(
        "{error:#}; not written: {} and the files beside it (previous files of those names are left as they were)",
        names.join(", ")
    )
}

/// Ends a stage whose loops skip the rest of their work once a signal asked to stop (a
/// render, a trace: `ugo::interrupt`): `Err` naming what was `during` and the `outputs`
/// not written, so that nothing partial is printed or written.
pub fn after_stage(during: impl FnOnce() -> String, outputs: &[&Path]) -> anyhow::Result<()> {
    ugo::interrupt::check(during).map_err(|e| not_written(e, outputs))
}
