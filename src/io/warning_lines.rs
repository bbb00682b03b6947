//! How warnings are told on a terminal (issue 37, point 4): one line each by default (the
//! first sentence, at most [`LINE`] characters; the whole text is in `/warnings` and with
//! `--verbose`), identical lines merged with a count, and which warnings are only notes.

use super::{NegativeEscape, Warning};

/// Longest one-line form of a warning, characters.
pub const LINE: usize = 200;

/// A negative escaped flux whose size and bound both stay below this share of the flux
/// emitted is a note about the discretization, not a warning: the closed office's
/// −0.004 % and a classroom's −0.088 % are far below what a lighting design can resolve.
pub const NOTE_SHARE: f64 = 1e-2;

impl Warning {
    /// Information rather than a warning: a closed scene's small negative escaped flux.
    /// Not counted as a warning, not refused by `--strict`.
    pub fn is_note(&self) -> bool {
        match self {
            Warning::NegativeEscape(NegativeEscape { escaped, either, emitted, .. }) => {
                escaped.abs().max(*either) < NOTE_SHARE * emitted.abs()
            }
            _ => false,
        }
    }
}

/// The first sentence of `text` (up to the first `". "` or `"; "`), cut to [`LINE`]
/// characters with an ellipsis.
pub fn one_line(text: &str) -> String {
    let end = [". ", "; "].iter().filter_map(|s| text.find(s)).min().unwrap_or(text.len());
    let first = &text[..end];
    if first.chars().count() <= LINE {
        return first.to_string();
    }
    let cut: String = first.chars().take(LINE - 1).collect();
    format!("{cut}…")
}

/// `lines` with identical ones merged, in order of first appearance, each with its count.
pub fn merged(lines: impl IntoIterator<Item = String>) -> Vec<(String, usize)> {
    let mut out: Vec<(String, usize)> = Vec::new();
    for line in lines {
        match out.iter_mut().find(|(l, _)| *l == line) {
            Some((_, n)) => *n += 1,
            None => out.push((line, 1)),
        }
    }
    out
}

/// The lines a terminal shows for `warnings`: one line each unless `verbose`, merged.
pub fn told(warnings: &[&Warning], verbose: bool) -> Vec<String> {
    let text = warnings.iter().map(|w| if verbose { w.to_string() } else { one_line(&w.to_string()) });
    merged(text).into_iter().map(|(line, n)| if n > 1 { format!("{line} (×{n})") } else { line }).collect()
}
