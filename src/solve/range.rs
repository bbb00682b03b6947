//! A value out of range in a solve (issue 18, item 2): an overflow or a NaN in the iterate,
//! or a norm (of the source term, the residual, the solution) that overflows, caught at the
//! iteration where it first appears and reported as what it is, never as a failure to
//! converge or a spectral radius.

use super::algorithm::Algorithm;
use std::fmt;

/// Where a solve met a value it cannot carry.
#[derive(Debug, Clone, PartialEq)]
pub struct OutOfRange {
    /// The algorithm that met it.
    pub method: Algorithm,
    /// The iteration at which it appeared; `None` before the first (the source term).
    pub iteration: Option<usize>,
    /// The norm that is not finite: `"the source term's norm ‖L0‖₂"`, `"the residual"`,
    /// `"the solution's norm ‖x‖₂"`.
    pub norm: &'static str,
    /// Its value.
    pub size: f64,
    /// The first unknown that is not finite, else the largest in magnitude.
    pub unknown: usize,
    /// The unknown's value.
    pub value: f64,
    /// The unknown's patch, surface and cell, when the caller knows them.
    pub place: Option<String>,
}

impl OutOfRange {
    /// `norm` of `vector` (the iterate, or the vector just made by `K`) is `size`, not
    /// finite: located at the first value of `vector` that is not finite, else its largest.
    pub fn of(
        method: Algorithm,
        iteration: Option<usize>,
        norm: &'static str,
        size: f64,
        vector: &[f64],
    ) -> OutOfRange {
        let unknown = vector.iter().position(|v| !v.is_finite()).unwrap_or_else(|| {
            (0..vector.len()).max_by(|&a, &b| vector[a].abs().total_cmp(&vector[b].abs())).unwrap_or(0)
        });
        let value = vector.get(unknown).copied().unwrap_or(f64::NAN);
        OutOfRange { method, iteration, norm, size, unknown, value, place: None }
    }
}

impl fmt::Display for OutOfRange {
    fn fmt(&self, f: &mut fmt::Formatter) -> fmt::Result {
        let at = self.place.clone().unwrap_or_else(|| format!("unknown {}", self.unknown));
        let (method, norm, size, value) = (self.method, self.norm, self.size, self.value);
        let when =
            self.iteration.map_or_else(|| "before its first iteration".to_string(), |n| format!("iteration {n}"));
        write!(f, "value out of range: {method}, {when}: ")?;
        if value.is_finite() {
            write!(f, "{norm} overflows ({size}) although every value is finite, the largest {value:e} cd/m² at {at}")?;
        } else {
            write!(f, "a value is {value} at {at} (an overflow or NaN in K·x), so {norm} is {size}")?;
        }
        write!(f, "; not a failure to converge: the source term or the kernel holds values the solve cannot carry")
    }
}
