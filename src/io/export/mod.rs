//! Exports of a saved kernel for other programs (issue 15, `docs/kernel-file.md`): the
//! explicit `K = B·G`, the system matrix `I − K` and the source term `L0` of
//! `x = L0 + K x` (`docs/design.md` §3), as Matrix Market text (`mtx.rs`, scipy's `mmread`) or
//! PETSc binary files (`petsc.rs`, PETSc's `MatLoad`/`VecLoad`). `K` is formed from the
//! stored `G` and blocks exactly as ugo's own explicit product. A hierarchy's kernel
//! (issue 36) is also written as its factors `P`, `Λ`, `R`, the balancing diagonals and
//! `B` (`kernel::hierarchy::Factors`), which hold it at the size of its links.

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

/// A matrix or a vector to write.
enum Item {
    Matrix(CsMat<f64>),
    Vector(Vec<f64>),
}

/// Writes `K`, `I − K` and `L0` of `stored` into `folder` as `K.<ext>`, `I-K.<ext>` and
/// `L0.<ext>`; the explicit product is refused over `limit` bytes. A hierarchy's file also
/// gets its factors (`P`, `Lambda`, `R`, the diagonals `receive` and `send`, the blocks `B`:
/// `K = B·diag(receive)·P·Λ·R·diag(send)`), and `K`, `I − K` only when they fit in `limit`.
/// Returns the paths.
pub fn export(stored: &StoredKernel, format: Format, folder: &Path, limit: u64) -> Result<Vec<PathBuf>, ExportError> {
    let factors = stored.kernel.g.hierarchy().map(|g| g.factors());
    let explicit = match (stored.kernel.explicit(limit), &factors) {
        (Ok(k), _) => Some(k),
        (Err(_), Some(_)) => None,
        (Err(e), None) => return Err(e.into()),
    };
    let mut items: Vec<(&str, Item, &str)> = Vec::new();
    if let Some(k) = explicit {
        let a = &CsMat::<f64>::eye(k.rows()) - &k;
        items.push(("K", Item::Matrix(k), "K = B*G of ugo's x = L0 + K x (docs/kernel-file.md)"));
        items.push(("I-K", Item::Matrix(a), "I - K of ugo's (I - K) x = L0 (docs/kernel-file.md)"));
    }
    items.push(("L0", Item::Vector(stored.l0.clone()), "L0 of ugo's x = L0 + K x, cd/m2 (docs/kernel-file.md)"));
    if let Some(f) = factors {
        let note = "of ugo's K = B*diag(receive)*P*Lambda*R*diag(send) (docs/kernel-file.md)";
        items.push(("P", Item::Matrix(f.push), note));
        items.push(("Lambda", Item::Matrix(f.links), note));
        items.push(("R", Item::Matrix(f.pull), note));
        items.push(("receive", Item::Vector(f.receive), note));
        items.push(("send", Item::Vector(f.send), note));
        items.push(("B", Item::Matrix(stored.kernel.materials_matrix()), note));
    }
    let mut paths = Vec::new();
    for (name, item, comment) in &items {
        let path = folder.join(format!("{name}.{}", format.extension()));
        match (format, item) {
            (Format::MatrixMarket, Item::Matrix(m)) => mtx::write_matrix(&path, m, &format!("{name} {comment}"))?,
            (Format::MatrixMarket, Item::Vector(v)) => mtx::write_vector(&path, v, &format!("{name} {comment}"))?,
            (Format::Petsc, Item::Matrix(m)) => petsc::write_matrix(&path, m)?,
            (Format::Petsc, Item::Vector(v)) => petsc::write_vector(&path, v)?,
        }
        paths.push(path);
    }
    Ok(paths)
}
