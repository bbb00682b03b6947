//! The exchange areas of pairs of patches (`docs/design.md` §3): both directions'
//! integrals of a pair, split by cells, their symmetric mean `T^{d,m}` times a visibility
//! fraction, gathered row by row and stored as one symmetric sparse matrix over
//! `(patch, cell)`. Direct pairs (`assembly.rs`) and the image pairs of plane mirrors
//! (`images.rs`) are both made of these.

use crate::geometry::{Mesh, Patch};
use crate::transfer::form_factor::{Binning, PairIntegral, Quadrature, binned_pair_integral, pair_integral};
use rayon::prelude::*;
use sprs::CsMat;

/// One exchanging pair `(i, j)`, `i < j`: its cell pieces `(d, m, T)` in `RowWork::cells`.
pub(super) struct Pair {
    /// The other patch.
    pub j: u32,
    /// Its first piece in `RowWork::cells`.
    pub first: u32,
    /// Its number of pieces.
    pub count: u32,
    /// `j`'s base-rule closure contribution, m².
    pub base_j: f64,
}

/// One row's share of the pair work.
#[derive(Default)]
pub(super) struct RowWork {
    /// The row's pairs, `j ≥ i`.
    pub pairs: Vec<Pair>,
    /// Their cell pieces `(d at i, m at j, T)`.
    pub cells: Vec<(u16, u16, f64)>,
    /// The row patch's base-rule closure contributions, m².
    pub closure: f64,
    /// Pairs integrated.
    pub visited: usize,
    /// Occlusion rays traced.
    pub rays: usize,
}

/// Both directions' integrals of a pair; binned pieces land in `from_a` (`(d at a, m at b)`)
/// and `from_b` (`(d at b, m at a)`).
pub(super) fn exchange(
    a: &Patch,
    b: &Patch,
    q: &Quadrature,
    binning: Option<&Binning>,
    from_a: &mut Vec<(u16, u16, f64)>,
    from_b: &mut Vec<(u16, u16, f64)>,
) -> (PairIntegral, PairIntegral) {
    match binning {
        None => (pair_integral(a, b, q), pair_integral(b, a, q)),
        Some(bins) => {
            from_a.clear();
            from_b.clear();
            (binned_pair_integral(a, b, q, bins, from_a), binned_pair_integral(b, a, q, bins, from_b))
        }
    }
}

/// Appends the symmetric cell pieces of a pair whose integrals are `ab` and `ba` (binned
/// into `from_a`, `from_b` when `binning`), visible fraction `v`, to `cells`: the one piece
/// `v (ab + ba)/2` without cells.
pub(super) fn push_pieces(
    (ab, ba): (PairIntegral, PairIntegral),
    from_a: &[(u16, u16, f64)],
    from_b: &[(u16, u16, f64)],
    binning: Option<&Binning>,
    v: f64,
    cells: &mut Vec<(u16, u16, f64)>,
) {
    match binning {
        None => cells.push((0, 0, 0.5 * (ab.adaptive + ba.adaptive) * v)),
        Some(_) => merge_pieces(from_a, from_b, v, cells),
    }
}

/// Symmetric cell pieces `T^{d,m} = v (S_ab^{d,m} + S_ba^{m,d}) / 2`, merged by cell pair
/// and appended to `cells`.
fn merge_pieces(from_a: &[(u16, u16, f64)], from_b: &[(u16, u16, f64)], v: f64, cells: &mut Vec<(u16, u16, f64)>) {
    let start = cells.len();
    cells.extend(from_a.iter().map(|&(d, m, t)| (d, m, 0.5 * v * t)));
    cells.extend(from_b.iter().map(|&(d, m, t)| (m, d, 0.5 * v * t)));
    merge_cells(cells, start);
}

/// Sorts `cells[start..]` by cell pair and sums the pieces of one cell pair.
pub(super) fn merge_cells(cells: &mut Vec<(u16, u16, f64)>, start: usize) {
    cells[start..].sort_unstable_by_key(|&(d, m, _)| (d, m));
    let mut write = start;
    for read in start..cells.len() {
        if write > start && cells[write - 1].0 == cells[read].0 && cells[write - 1].1 == cells[read].1 {
            cells[write - 1].2 += cells[read].2;
        } else {
            cells[write] = cells[read];
            write += 1;
        }
    }
    cells.truncate(write);
}

/// The symmetric exchange areas `T[(i,d),(j,m)]` as CSR rows over `(patch, cell)`. A pair
/// of a patch with itself (`j = i`, a patch seeing its own image) must hold each cell pair
/// once, with `d ≤ m`.
pub(super) fn sparse_rows(mesh: &Mesh, k: usize, work: &[RowWork]) -> CsMat<f64> {
    let rows = mesh.len() * k;
    let mut counts = vec![0usize; rows + 1];
    for (i, w) in work.iter().enumerate() {
        for p in &w.pairs {
            for &(cd, cm, _) in &w.cells[p.first as usize..(p.first + p.count) as usize] {
                counts[i * k + cd as usize + 1] += 1;
                if (i, cd) != (p.j as usize, cm) {
                    counts[p.j as usize * k + cm as usize + 1] += 1;
                }
            }
        }
    }
    for r in 0..rows {
        counts[r + 1] += counts[r];
    }
    let indptr = counts.clone();
    let mut fill = counts;
    let mut entries = vec![(0usize, 0.0f64); indptr[rows]];
    for (i, w) in work.iter().enumerate() {
        for p in &w.pairs {
            let j = p.j as usize;
            for &(cd, cm, t) in &w.cells[p.first as usize..(p.first + p.count) as usize] {
                let (ri, rj) = (i * k + cd as usize, j * k + cm as usize);
                entries[fill[ri]] = (rj, t);
                fill[ri] += 1;
                if ri != rj {
                    entries[fill[rj]] = (ri, t);
                    fill[rj] += 1;
                }
            }
        }
    }
    let mut chunks: Vec<&mut [(usize, f64)]> = Vec::with_capacity(rows);
    let mut rest = entries.as_mut_slice();
    for r in 0..rows {
        let (row, tail) = rest.split_at_mut(indptr[r + 1] - indptr[r]);
        chunks.push(row);
        rest = tail;
    }
    chunks.par_iter_mut().for_each(|row| row.sort_unstable_by_key(|e| e.0));
    let (indices, data) = entries.into_iter().unzip();
    CsMat::new((rows, rows), indptr, indices, data)
}
