//! Assembly of the transport matrix `G` (`design.md` §3) for the one-cell direction set:
//! `G_ij = F_ij` with occlusion, exactly reciprocal and closed after balancing.
//!
//! Every unordered pair of mutually facing patches is visited once, in parallel over
//! rows: both exchange-area estimates ([`pair_integral`] over `i` and over `j`), the
//! shared visibility fraction, and both patches' base-rule closure contributions. The
//! balanced exchange areas `T` become `G_ij = T_ij / A_i`. A row's closure target is its
//! base-rule closure where that agrees with the adaptive row sum to `1e-3` (so closed
//! convex rooms close to round-off), else the adaptive row sum (patches crossed by a
//! contact line, such as a floor patch partly under a block).

use super::balance::{BalanceReport, balance};
use super::form_factor::{Quadrature, pair_integral};
use super::occlusion::{POINTS, sample_points, visible_fraction};
use crate::geometry::{Mesh, Patch};
use crate::visibility::{NO_BLOCKER, Visibility};
use rayon::prelude::*;
use sprs::CsMat;

/// The assembled transport matrix and what it cost.
#[derive(Debug, Clone)]
pub struct Transport {
    /// `G`, `N × N` (one direction cell).
    pub g: CsMat<f64>,
    pub balance: BalanceReport,
    /// Unordered patch pairs that face each other and were integrated.
    pub pairs: usize,
    /// Occlusion rays traced.
    pub rays: usize,
}

/// The base-rule closure is exact (to round-off) where no occluder or contact line
/// crosses the patch's view; where it differs from the adaptive row sum by more than
/// this, something it cannot resolve does, and the adaptive sum is the target instead.
const TRUSTED_CLOSURE: f64 = 1e-3;

/// One row's share of the pair work: `(j, T_ij, base closure of j towards i)`.
struct RowWork {
    entries: Vec<(u32, f64, f64)>,
    closure: f64,
    pairs: usize,
    rays: usize,
}

/// Assembles `G`. `progress` is called with the number of pairs just finished.
pub fn assemble(
    mesh: &Mesh,
    visibility: &Visibility,
    quadrature: &Quadrature,
    progress: &(dyn Fn(u64) + Sync),
) -> Transport {
    let n = mesh.len();
    let points: Vec<[glam::DVec3; POINTS]> = mesh.patches.par_iter().map(sample_points).collect();
    let work: Vec<RowWork> = (0..n)
        .into_par_iter()
        .map(|i| {
            let row = row_work(mesh, visibility, quadrature, &points, i);
            progress((n - i - 1) as u64);
            row
        })
        .collect();

    let mut targets: Vec<f64> = work.iter().map(|w| w.closure).collect();
    let mut rows: Vec<Vec<(u32, f64)>> = vec![Vec::new(); n];
    for (i, w) in work.iter().enumerate() {
        for &(j, t, base_j) in &w.entries {
            rows[j as usize].push((i as u32, t));
            targets[j as usize] += base_j;
        }
    }
    for (i, w) in work.iter().enumerate() {
        rows[i].extend(w.entries.iter().map(|&(j, t, _)| (j, t)));
    }
    let pairs = work.iter().map(|w| w.pairs).sum::<usize>();
    let rays = work.iter().map(|w| w.rays).sum::<usize>();
    drop(work);

    for (i, row) in rows.iter().enumerate() {
        let adaptive: f64 = row.iter().map(|&(_, t)| t).sum();
        if (targets[i] - adaptive).abs() > TRUSTED_CLOSURE * adaptive {
            targets[i] = adaptive;
        }
    }
    let (d, report) = balance(&rows, &targets);
    let mut indptr = Vec::with_capacity(n + 1);
    let (mut indices, mut data) = (Vec::new(), Vec::new());
    indptr.push(0);
    for (i, row) in rows.iter().enumerate() {
        for &(j, t) in row {
            indices.push(j as usize);
            data.push(d[i] * t * d[j as usize] / mesh.patches[i].area);
        }
        indptr.push(indices.len());
    }
    Transport { g: CsMat::new((n, n), indptr, indices, data), balance: report, pairs, rays }
}

fn row_work(
    mesh: &Mesh,
    visibility: &Visibility,
    q: &Quadrature,
    points: &[[glam::DVec3; POINTS]],
    i: usize,
) -> RowWork {
    let a = &mesh.patches[i];
    let mut row = RowWork { entries: Vec::new(), closure: 0.0, pairs: 0, rays: 0 };
    let mut blocker = NO_BLOCKER;
    for j in i + 1..mesh.len() {
        let b = &mesh.patches[j];
        if !facing(a, b) {
            continue;
        }
        let (ab, ba) = (pair_integral(a, b, q), pair_integral(b, a, q));
        if ab.adaptive <= 0.0 && ba.adaptive <= 0.0 {
            continue;
        }
        row.pairs += 1;
        let visible = visible_fraction(visibility, a, &points[i], b, &points[j], &mut blocker);
        row.rays += visible.rays;
        let v = visible.fraction;
        if v > 0.0 {
            row.entries.push((j as u32, 0.5 * (ab.adaptive + ba.adaptive) * v, ba.base * v));
            row.closure += ab.base * v;
        }
    }
    row
}

/// True when some part of each patch lies strictly in front of the other.
pub fn facing(a: &Patch, b: &Patch) -> bool {
    let ahead = |p: &Patch, q: &Patch| {
        let eps = 1e-9 * (p.area + q.area).sqrt();
        q.polygon.vertices().iter().any(|v| (*v - p.centroid).dot(p.normal) > eps)
    };
    ahead(a, b) && ahead(b, a)
}
