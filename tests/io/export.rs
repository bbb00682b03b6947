//! `ugo export` (docs/kernel-file.md): the PETSc binary files read back by a small reader
//! of the format (big-endian, class ids 1211216 and 1211214, int32 indices, f64 values)
//! hold exactly ugo's `K = B·G`, `I − K` and `L0`; a file without a kernel is refused.
//! (The Matrix Market files are read by scipy in `kernel_check.py`.)

use super::kernel_file::{room, run};
use crate::support::{scratch, ugo};
use sprs::CsMat;
use std::path::Path;

fn be_i32(bytes: &[u8], at: &mut usize) -> i32 {
    let v = i32::from_be_bytes(bytes[*at..*at + 4].try_into().unwrap());
    *at += 4;
    v
}

fn be_f64(bytes: &[u8], at: &mut usize) -> f64 {
    let v = f64::from_be_bytes(bytes[*at..*at + 8].try_into().unwrap());
    *at += 8;
    v
}

/// A PETSc binary `Mat` as CSR.
fn petsc_mat(path: &Path) -> CsMat<f64> {
    let bytes = std::fs::read(path).unwrap();
    let at = &mut 0;
    assert_eq!(be_i32(&bytes, at), 1_211_216, "MAT_FILE_CLASSID");
    let (m, n, nz) = (be_i32(&bytes, at) as usize, be_i32(&bytes, at) as usize, be_i32(&bytes, at) as usize);
    let lengths: Vec<usize> = (0..m).map(|_| be_i32(&bytes, at) as usize).collect();
    let indices: Vec<usize> = (0..nz).map(|_| be_i32(&bytes, at) as usize).collect();
    let data: Vec<f64> = (0..nz).map(|_| be_f64(&bytes, at)).collect();
    assert_eq!(*at, bytes.len(), "nothing after the values");
    let indptr: Vec<usize> = std::iter::once(0)
        .chain(lengths.iter().scan(0, |s, l| {
            *s += l;
            Some(*s)
        }))
        .collect();
    CsMat::new((m, n), indptr, indices, data)
}

/// A PETSc binary `Vec`.
fn petsc_vec(path: &Path) -> Vec<f64> {
    let bytes = std::fs::read(path).unwrap();
    let at = &mut 0;
    assert_eq!(be_i32(&bytes, at), 1_211_214, "VEC_FILE_CLASSID");
    let n = be_i32(&bytes, at) as usize;
    let v = (0..n).map(|_| be_f64(&bytes, at)).collect();
    assert_eq!(*at, bytes.len());
    v
}

#[test]
fn the_petsc_files_hold_exactly_k_i_minus_k_and_l0() {
    let dir = scratch("export-petsc");
    let case = room(&dir, "room.toml", str::to_string);
    let out = dir.join("room.h5");
    run(&["solve", case.to_str().unwrap(), "--save-kernel", "-o", out.to_str().unwrap()]);
    run(&["export", out.to_str().unwrap(), "--format", "petsc", "-o", dir.to_str().unwrap()]);
    let stored = ugo::io::read_kernel(&out).unwrap();
    let k = stored.kernel.explicit(u64::MAX).unwrap();
    let n = k.rows();
    assert_eq!(petsc_mat(&dir.join("K.petsc")), k);
    let a = petsc_mat(&dir.join("I-K.petsc"));
    assert_eq!(a.nnz(), k.nnz() + n, "K has no diagonal; I − K adds it");
    for (v, (i, j)) in a.iter() {
        let expected = if i == j { 1.0 } else { -k.get(i, j).copied().unwrap_or(0.0) };
        assert_eq!(*v, expected, "(I − K)[{i}, {j}]");
    }
    assert_eq!(petsc_vec(&dir.join("L0.petsc")), stored.l0);
    assert!(stored.l0.iter().any(|&l| l > 0.0), "the bulb lights the room");
}

#[test]
fn a_solution_without_a_kernel_is_refused() {
    let dir = scratch("export-none");
    let out = dir.join("furnace.h5");
    run(&["solve", "cases/furnace-box.toml", "--patch-size", "0.25", "-o", out.to_str().unwrap()]);
    let o = ugo(&["export", out.to_str().unwrap(), "--format", "mtx", "-o", dir.to_str().unwrap()]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(!o.status.success() && err.contains("no /kernel group") && err.contains("--save-kernel"), "{err}");
    assert!(!dir.join("K.mtx").exists());
}
