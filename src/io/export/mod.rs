//! Exports of a saved kernel for other programs (issue 15, `docs/kernel-file.md`): the
//! explicit `K = B·G`, the system matrix `I − K` and the source term `L0` of
//! `x = L0 + K x` (`docs/design.md` §3), as Matrix Market text (`mtx.rs`, scipy's `mmread`) or
//! PETSc binary files (`petsc.rs`, PETSc's `MatLoad`/`VecLoad`). `K` is formed from the
//! stored `G` and blocks exactly as ugo's own explicit product.

mod error;
mod mtx;
mod petsc;

pub use error::ExportError;

use super::StoredKernel;
use sprs::CsMat;
use std::path::{Path, PathBuf};

/// The file formats of an export.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Format {
    /// Matrix Market: `coordinate real general` matrices, an `array real general` vector.
    MatrixMarket,
    /// PETSc binary: big-endian, int32 indices, f64 values.
    Petsc,
}

impl Format {
    /// The extension of the files written.
    pub fn extension(self) -> &'static str {
        match self {
            Format::MatrixMarket => "mtx",
            Format::Petsc => "petsc",
        }
    }
}

/// Writes `K`, `I − K` and `L0` of `stored` into `folder` as `K.<ext>`, `I-K.<ext>` and
/// `L0.<ext>`; the explicit product is refused over `limit` bytes. Returns the paths.
pub fn export(stored: &StoredKernel, format: Format, folder: &Path, limit: u64) -> Result<Vec<PathBuf>, ExportError> {
    let k = stored.kernel.explicit(limit)?;
    let a = &CsMat::<f64>::eye(k.rows()) - &k;
    let path = |name: &str| folder.join(format!("{name}.{}", format.extension()));
    let paths = vec![path("K"), path("I-K"), path("L0")];
    match format {
        Format::MatrixMarket => {
            mtx::write_matrix(&paths[0], &k, "K = B*G of ugo's x = L0 + K x (docs/kernel-file.md)")?;
            mtx::write_matrix(&paths[1], &a, "I - K of ugo's (I - K) x = L0 (docs/kernel-file.md)")?;
            mtx::write_vector(&paths[2], &stored.l0, "L0 of ugo's x = L0 + K x, cd/m2 (docs/kernel-file.md)")?;
        }
        Format::Petsc => {
            petsc::write_matrix(&paths[0], &k)?;
            petsc::write_matrix(&paths[1], &a)?;
            petsc::write_vector(&paths[2], &stored.l0)?;
        }
    }
    Ok(paths)
}
