//! The numbers of a photometric file as a stream of tokens, each with its line, so that
//! every error can say where it is and what was expected there.

use super::error::PhotometryError;
use std::path::Path;

/// Whitespace- or comma-separated tokens of a text, with their 1-based line numbers.
pub struct Tokens<'a> {
    file: &'a Path,
    items: Vec<(usize, &'a str)>,
    next: usize,
    /// Line of the end of the file (for "found the end of the file").
    end: usize,
}

impl<'a> Tokens<'a> {
    /// The tokens of `lines`, the first of which is line `first` of `file`.
    pub fn new(file: &'a Path, lines: impl Iterator<Item = &'a str>, first: usize) -> Tokens<'a> {
        let mut items = Vec::new();
        let mut end = first.saturating_sub(1).max(1);
        for (offset, line) in lines.enumerate() {
            let number = first + offset;
            end = number;
            items.extend(
                line.split(|c: char| c.is_whitespace() || c == ',').filter(|t| !t.is_empty()).map(|t| (number, t)),
            );
        }
        Tokens { file, items, next: 0, end }
    }

    /// The line of the token read last (or of the end of the file).
    pub fn line(&self) -> usize {
        self.next.checked_sub(1).map_or(self.end, |i| self.items[i].0)
    }

    /// An error on the line of the token read last.
    pub fn error(&self, message: impl Into<String>) -> PhotometryError {
        PhotometryError::at(self.file, self.line(), message)
    }

    /// The next finite number; `what` names it for the error.
    pub fn number(&mut self, what: &dyn Fn() -> String) -> Result<f64, PhotometryError> {
        let Some(&(line, token)) = self.items.get(self.next) else {
            return Err(PhotometryError::at(
                self.file,
                self.end,
                format!("expected {}, found the end of the file", what()),
            ));
        };
        self.next += 1;
        match token.parse::<f64>() {
            Ok(x) if x.is_finite() => Ok(x),
            _ => Err(PhotometryError::at(self.file, line, format!("expected {}, got '{token}'", what()))),
        }
    }

    /// The next number, which must be an integer within `range`.
    pub fn integer(&mut self, what: &str, range: std::ops::RangeInclusive<i64>) -> Result<i64, PhotometryError> {
        let x = self.number(&|| what.to_string())?;
        let n = x as i64;
        if x.fract() != 0.0 || !range.contains(&n) {
            let bound = if *range.end() == i64::MAX {
                format!("at least {}", range.start())
            } else {
                format!("{} to {}", range.start(), range.end())
            };
            return Err(self.error(format!("expected {what} ({bound}), got {x}")));
        }
        Ok(n)
    }

    /// The token that follows the last one expected, if any.
    pub fn rest(&self) -> Option<(usize, &'a str)> {
        self.items.get(self.next).copied()
    }
}
