//! PETSc's binary format, as `MatLoad` and `VecLoad` read it (PETSc manual, "Viewers:
//! binary"): big-endian throughout; a matrix is the class id 1211216, rows, columns and
//! non-zeros (int32), each row's length (int32), every column index row by row (int32),
//! every value (f64); a vector is the class id 1211214, its length (int32) and its values
//! (f64).

use super::error::ExportError;
use crate::io::atomic::atomic_stream;
use sprs::CsMat;
use std::path::Path;

/// `MAT_FILE_CLASSID`.
pub const MAT_CLASS_ID: i32 = 1_211_216;
/// `VEC_FILE_CLASSID`.
pub const VEC_CLASS_ID: i32 = 1_211_214;

/// Writes the CSR matrix `m` to `path`.
pub(super) fn write_matrix(path: &Path, m: &CsMat<f64>) -> Result<(), ExportError> {
    let rows = int32("rows", m.rows())?;
    let cols = int32("columns", m.cols())?;
    let nnz = int32("non-zeros", m.nnz())?;
    atomic_stream(path, |w| {
        [MAT_CLASS_ID, rows, cols, nnz].iter().try_for_each(|x| w.write_all(&x.to_be_bytes()))?;
        let indptr = m.indptr();
        let indptr = indptr.raw_storage();
        indptr.windows(2).try_for_each(|r| w.write_all(&((r[1] - r[0]) as i32).to_be_bytes()))?;
        m.indices().iter().try_for_each(|&c| w.write_all(&(c as i32).to_be_bytes()))?;
        m.data().iter().try_for_each(|v| w.write_all(&v.to_be_bytes()))
    })?;
    Ok(())
}

/// Writes `v` to `path`.
pub(super) fn write_vector(path: &Path, v: &[f64]) -> Result<(), ExportError> {
    let n = int32("the vector's length", v.len())?;
    atomic_stream(path, |w| {
        [VEC_CLASS_ID, n].iter().try_for_each(|x| w.write_all(&x.to_be_bytes()))?;
        v.iter().try_for_each(|x| w.write_all(&x.to_be_bytes()))
    })?;
    Ok(())
}

fn int32(what: &'static str, count: usize) -> Result<i32, ExportError> {
    i32::try_from(count).map_err(|_| ExportError::TooManyForPetsc { what, count })
}
