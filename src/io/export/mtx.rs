//! Matrix Market text (NIST's exchange format, read by `scipy.io.mmread`, MATLAB, Julia):
//! a sparse matrix as `coordinate real general`, one `row column value` line per
//! non-zero, 1-based; a vector as an `array real general` column. Values are written in
//! their shortest round-trip form, so a reader gets every bit back.

use crate::io::IoError;
use crate::io::atomic::atomic_stream;
use sprs::CsMat;
use std::path::Path;

/// Writes `m` to `path` with a `%` comment line.
pub(super) fn write_matrix(path: &Path, m: &CsMat<f64>, comment: &str) -> Result<(), IoError> {
    atomic_stream(path, |w| {
        writeln!(w, "%%MatrixMarket matrix coordinate real general")?;
        writeln!(w, "% {comment}")?;
        writeln!(w, "{} {} {}", m.rows(), m.cols(), m.nnz())?;
        for (v, (i, j)) in m.iter() {
            writeln!(w, "{} {} {v:e}", i + 1, j + 1)?;
        }
        Ok(())
    })
}

/// Writes `v` to `path` as an `n × 1` array with a `%` comment line.
pub(super) fn write_vector(path: &Path, v: &[f64], comment: &str) -> Result<(), IoError> {
    atomic_stream(path, |w| {
        writeln!(w, "%%MatrixMarket matrix array real general")?;
        writeln!(w, "% {comment}")?;
        writeln!(w, "{} 1", v.len())?;
        v.iter().try_for_each(|x| writeln!(w, "{x:e}"))
    })
}
