//! The light that plane mirrors carry between patches, by virtual images (`docs/design.md`
//! (3.10), `docs/mirrors.md`): for each plane mirror `M` (`transfer::image`) and each pair of
//! patches `(i, j)` in front of it, neither a mirror, the exchange area of `i` with `j`'s
//! image `j′`, `ρ_M v T_{ij′}^{d,m}` (`v` the share of the segments between the pair's
//! stratified points that pass through `M`), binned as a direct pair: `d` the cell the light
//! arrives in at `i` (from the mirror point), `m` the cell it leaves `j` in (towards it).
//!
//! These exchange areas are symmetric (`A_i F_{ij′} = A_j F_{ji′}`). Where the mirrors are
//! closed (every ray they reflect lands on a patch) they are balanced on their own
//! (`balance.rs`) so that each row `(i, d)` (or, failing that, each patch) carries `ρ_M`
//! times the balanced exchange area of `(i, d)` with the mirror: the images deliver
//! exactly the light the mirror reflects.
//! The mirror's columns of the direct `G` are then dropped (its light reaches the others
//! only through its images); its rows stay, so its stored luminance (the cell-to-cell
//! reflection of what arrives at it) is what readouts and renders look at.

use super::balance::balance;
use super::pairs::{Pair, RowWork, exchange, merge_cells, push_pieces};
use crate::geometry::{Mesh, facing};
use crate::transfer::form_factor::{Binning, Quadrature};
use crate::transfer::image::{PlaneMirror, image_fraction};
use crate::transfer::occlusion::POINTS;
use crate::visibility::Visibility;
use glam::DVec3;
use rayon::prelude::*;
use sprs::CsMat;

/// Largest relative row-sum mismatch with which the images' balancing is kept.
const BALANCED: f64 = 1e-9;
/// Largest row correction (`|D² − 1|`) with which the images' balancing is kept.
const MOST_CORRECTION: f64 = 3.0;
/// A mirror patch is closed where its balanced row sums carry its exposed area to this,
/// relative to its area: nothing but the quadrature's own error escapes from it (the mirror
/// room's mirror carries 1.001 to 1.003 of its area: its view of the ceiling behind the
/// lamp 1 cm under it is counted twice, in part).
const CLOSED: f64 = 1e-2;

/// The plane mirrors of a mesh of `n` patches, and which patches they hold.
pub(super) struct Mirrors<'a> {
    /// The mirrors.
    pub planes: &'a [PlaneMirror],
    /// True for every patch of a plane mirror.
    pub held: Vec<bool>,
}

impl<'a> Mirrors<'a> {
    /// `planes` over a mesh of `n` patches.
    pub fn new(n: usize, planes: &'a [PlaneMirror]) -> Mirrors<'a> {
        let mut held = vec![false; n];
        planes.iter().flat_map(|m| &m.patches).for_each(|&p| held[p as usize] = true);
        Mirrors { planes, held }
    }
}

/// The image exchange areas of row `i`: one [`Pair`] per `j ≥ i` that sees `i` through some
/// mirror, its pieces summed over the mirrors.
pub(super) fn image_row(
    mesh: &Mesh,
    visibility: &Visibility,
    mirrors: &Mirrors,
    q: &Quadrature,
    binning: Option<&Binning>,
    points: &[[DVec3; POINTS]],
    i: usize,
) -> RowWork {
    let (held, mut row) = (&mirrors.held, RowWork::default());
    if held[i] {
        return row;
    }
    let a = &mesh.patches[i];
    let (mut from_a, mut from_b) = (Vec::new(), Vec::new());
    let fronts: Vec<&PlaneMirror> = mirrors.planes.iter().filter(|m| m.reflectance > 0.0 && m.in_front(a)).collect();
    for j in i..mesh.len() {
        if held[j] {
            continue;
        }
        let first = row.cells.len();
        for mirror in fronts.iter().filter(|m| m.in_front(&mesh.patches[j])) {
            let image = mirror.image(&mesh.patches[j]);
            if !facing(a, &image) {
                continue;
            }
            row.visited += 1;
            let visible = image_fraction(visibility, mirror, a, &points[i], &mesh.patches[j], &points[j]);
            row.rays += visible.rays;
            if visible.fraction <= 0.0 {
                continue;
            }
            let integrals = exchange(a, &image, q, binning, &mut from_a, &mut from_b);
            push_pieces(integrals, &from_a, &from_b, binning, mirror.reflectance * visible.fraction, &mut row.cells);
        }
        if row.cells.len() == first {
            continue;
        }
        if j == i {
            // a patch seeing itself: each cell pair once, `d ≤ m`, holding the mean of both orders
            for c in &mut row.cells[first..] {
                if c.0 > c.1 {
                    *c = (c.1, c.0, c.2);
                }
                if c.0 != c.1 {
                    c.2 *= 0.5;
                }
            }
        }
        merge_cells(&mut row.cells, first);
        let count = (row.cells.len() - first) as u32;
        row.pairs.push(Pair { j: j as u32, first: first as u32, count, base_j: 0.0 });
    }
    row
}

/// The scaling `D` of the image exchange areas `images`. Where every mirror patch is closed
/// (its balanced direct row sums, `direct` scaled by `scale`, carry its exposed area to
/// [`CLOSED`]: every reflected ray lands on a patch), each row `(i, d)` carries `ρ_M` times
/// the balanced exchange area of `(i, d)` with the patches of `M`; where that needs
/// corrections beyond [`MOST_CORRECTION`] (the images' pieces and the mirror's fall into
/// different cells near a cell's edge), each patch carries that in total, shared among its
/// cells as the images' own. All ones (the raw images) in an open scene or where neither
/// converges.
pub(super) fn balance_images(
    mesh: &Mesh,
    mirrors: &[PlaneMirror],
    k: usize,
    direct: &CsMat<f64>,
    scale: &[f64],
    images: &CsMat<f64>,
) -> Vec<f64> {
    let mut reflectance = vec![0.0; mesh.len()];
    for m in mirrors {
        m.patches.iter().for_each(|&p| reflectance[p as usize] = m.reflectance);
    }
    let carried = |r: usize| -> f64 {
        direct.outer_view(r).map_or(0.0, |row| row.iter().map(|(c, v)| v * scale[r] * scale[c]).sum())
    };
    let closed = mirrors.iter().flat_map(|m| &m.patches).all(|&p| {
        let patch = &mesh.patches[p as usize];
        let carries: f64 = (p as usize * k..(p as usize + 1) * k).map(carried).sum();
        (carries - patch.exposed).abs() <= CLOSED * patch.area
    });
    let ones = vec![1.0; images.rows()];
    if !closed {
        return ones;
    }
    let by_cell: Vec<f64> = (0..direct.rows())
        .into_par_iter()
        .map(|r| {
            direct.outer_view(r).map_or(0.0, |row| {
                let seen = row.iter().filter(|&(c, _)| reflectance[c / k] > 0.0);
                seen.map(|(c, v)| reflectance[c / k] * v * scale[r] * scale[c]).sum()
            })
        })
        .collect();
    let (d, report) = balance(images, &by_cell);
    if report.residual <= BALANCED && report.max_correction <= MOST_CORRECTION {
        return d;
    }
    let raw: Vec<f64> = images.outer_iterator().map(|row| row.data().iter().sum()).collect();
    let mut by_patch = vec![0.0; raw.len()];
    for p in 0..mesh.len() {
        let cells = p * k..(p + 1) * k;
        let (total, split) = (by_cell[cells.clone()].iter().sum::<f64>(), raw[cells.clone()].iter().sum::<f64>());
        if split > 0.0 {
            cells.for_each(|r| by_patch[r] = total * raw[r] / split);
        }
    }
    let (d, report) = balance(images, &by_patch);
    if report.residual <= BALANCED && report.max_correction <= MOST_CORRECTION {
        return d;
    }
    ones
}

/// `G`: the direct exchange areas `direct` scaled by `d`, without the columns of mirror
/// patches (`held`), plus the image exchange areas `images` scaled by `e`, per exposed area
/// of the row's patch.
pub(super) fn combine(
    mesh: &Mesh,
    k: usize,
    held: &[bool],
    (direct, d): (&CsMat<f64>, &[f64]),
    (images, e): (&CsMat<f64>, &[f64]),
) -> CsMat<f64> {
    let rows: Vec<Vec<(usize, f64)>> = (0..direct.rows())
        .into_par_iter()
        .map(|r| {
            let patch = &mesh.patches[r / k];
            let mut row: Vec<(usize, f64)> = Vec::new();
            if let Some(view) = direct.outer_view(r) {
                row.extend(view.iter().filter(|&(c, _)| !held[c / k]).map(|(c, v)| (c, v * d[r] * d[c])));
            }
            if let Some(view) = images.outer_view(r) {
                row.extend(view.iter().map(|(c, v)| (c, v * e[r] * e[c])));
            }
            row.sort_unstable_by_key(|x| x.0);
            let mut merged: Vec<(usize, f64)> = Vec::with_capacity(row.len());
            for (c, v) in row {
                match merged.last_mut() {
                    Some(last) if last.0 == c => last.1 += v,
                    _ => merged.push((c, v)),
                }
            }
            merged.iter_mut().for_each(|x| x.1 = patch.per_exposed_area(x.1));
            merged
        })
        .collect();
    let mut indptr = Vec::with_capacity(rows.len() + 1);
    indptr.push(0);
    for row in &rows {
        indptr.push(indptr.last().copied().unwrap_or(0) + row.len());
    }
    let (indices, data) = rows.into_iter().flatten().unzip();
    CsMat::new((direct.rows(), direct.cols()), indptr, indices, data)
}
