//! Assembly of the transport matrix `G` (`docs/design.md` §3): `G[(i,d),(j,m)] = F_ij^{d,m}`
//! with occlusion, exactly reciprocal and closed after balancing.
//!
//! Every unordered pair of mutually facing patches is visited once, in parallel over
//! rows: both exchange-area estimates (integrated over `i` and over `j`, split by cells
//! when `K > 1`), their mean (so `A_i F_ij^{d,m} = A_j F_ji^{m,d}` holds exactly), the
//! shared visibility fraction, and both patches' base-rule closure contributions. The
//! exchange areas of a patch that straddles a solid's foot print are taken from the share
//! of its points outside to its exposed area (`e_i`, `transfer::exposure`). They are then
//! balanced row by row, `(patch, cell)`, and become
//! `G[(i,d),(j,m)] = D_(i,d) D_(j,m) e_i e_j T_ij^{d,m} / (φ_i A_i)`, `φ_i A_i` the exposed
//! area ((3.11); see [`cell_targets`] for what each row must carry). Plane mirrors carry
//! light between patches by their images (`images.rs`, `docs/design.md` (3.10)) instead of
//! their columns of `G`.

use super::balance::balance;
use super::images::{Mirrors, balance_images, combine, image_row};
use super::pairs::{Pair, RowWork, exchange, push_pieces, sparse_rows};
use crate::directions::DirectionSet;
use crate::geometry::{Mesh, facing};
use crate::interrupt::Interrupted;
use crate::kernel::BalanceReport;
use crate::transfer::exposure::point_corrections;
use crate::transfer::form_factor::{Binning, Quadrature};
use crate::transfer::image::PlaneMirror;
use crate::transfer::occlusion::{POINTS, sample_points, visible_fraction};
use crate::visibility::{NO_BLOCKER, Visibility};
use rayon::prelude::*;
use sprs::CsMat;

/// The assembled transport matrix and what it cost.
#[derive(Debug, Clone)]
pub struct Assembled {
    /// `G`, `N·K × N·K`.
    pub g: CsMat<f64>,
    /// How balancing moved the exchange areas.
    pub balance: BalanceReport,
    /// Unordered patch pairs that face each other (directly or by a mirror image) and were
    /// integrated.
    pub pairs: usize,
    /// Occlusion rays traced.
    pub rays: usize,
}

/// The base-rule closure is trusted where it agrees with the adaptive row sum to this.
const TRUSTED_CLOSURE: f64 = 1e-3;

/// Assembles `G` for `directions`, the light by way of `mirrors` carried by their images.
/// `progress` is called with the number of direct pairs just finished. A stop asked for by a
/// signal (`crate::interrupt`) skips the rows not yet begun and ends with [`Interrupted`].
pub fn assemble(
    mesh: &Mesh,
    visibility: &Visibility,
    directions: &DirectionSet,
    quadrature: &Quadrature,
    mirrors: &[PlaneMirror],
    progress: &(dyn Fn(u64) + Sync),
) -> Result<Assembled, Interrupted> {
    let n = mesh.len();
    let k = directions.len();
    let points: Vec<[glam::DVec3; POINTS]> = mesh.patches.par_iter().map(sample_points).collect();
    let binning = (k > 1).then(|| Binning::new(directions));
    let stride = row_stride(n);
    let shuffled: Vec<RowWork> = (0..n)
        .into_par_iter()
        .map(|k| {
            if crate::interrupt::requested(String::new).is_some() {
                return RowWork::default();
            }
            let i = k * stride % n;
            let row = row_work(mesh, visibility, quadrature, binning.as_ref(), &points, i);
            progress((n - i - 1) as u64);
            row
        })
        .collect();
    let mut work: Vec<RowWork> = (0..n).map(|_| RowWork::default()).collect();
    for (k, row) in shuffled.into_iter().enumerate() {
        work[k * stride % n] = row;
    }
    crate::interrupt::check(|| {
        let pairs: usize = work.iter().map(|w| w.visited).sum();
        format!("the assembly of G ({pairs} facing pairs of its {n} patches integrated)")
    })?;
    let exposure = point_corrections(mesh, visibility);
    let exchange = to_exposed_areas(sparse_rows(mesh, k, &work), &exposure, k);
    let targets = |by_cell| cell_targets(mesh, directions, &work, &exchange, &exposure, by_cell);
    let (mut d, mut report) = balance(&exchange, &targets(true));
    report.by_cell = true;
    if report.residual > BALANCED || report.max_correction > MOST_CORRECTION {
        (d, report) = balance(&exchange, &targets(false));
    }
    let (mut pairs, mut rays) = (work.iter().map(|w| w.visited).sum(), work.iter().map(|w| w.rays).sum());
    if mirrors.is_empty() {
        let mut g = exchange;
        for (r, mut row) in g.outer_iterator_mut().enumerate() {
            let patch = &mesh.patches[r / k];
            for (c, v) in row.iter_mut() {
                *v = patch.per_exposed_area(*v * d[r] * d[c]);
            }
        }
        return Ok(Assembled { g, balance: report, pairs, rays });
    }
    let planes = Mirrors::new(n, mirrors);
    let images: Vec<RowWork> = (0..n)
        .into_par_iter()
        .map(|i| match crate::interrupt::requested(String::new) {
            Some(_) => RowWork::default(),
            None => image_row(mesh, visibility, &planes, quadrature, binning.as_ref(), &points, i),
        })
        .collect();
    crate::interrupt::check(|| format!("the mirror images of G ({n} patches)"))?;
    pairs += images.iter().map(|w| w.visited).sum::<usize>();
    rays += images.iter().map(|w| w.rays).sum::<usize>();
    let images = to_exposed_areas(sparse_rows(mesh, k, &images), &exposure, k);
    let e = balance_images(mesh, mirrors, k, &exchange, &d, &images);
    let g = combine(mesh, k, &planes.held, (&exchange, &d), (&images, &e));
    Ok(Assembled { g, balance: report, pairs, rays })
}

/// `T[(i,d),(j,m)] e_i e_j`: the exchange areas integrated through the patches' points taken
/// to their exposed areas (`e`, [`point_corrections`]; `K` cells a patch).
fn to_exposed_areas(mut t: CsMat<f64>, e: &[f64], k: usize) -> CsMat<f64> {
    for (r, mut row) in t.outer_iterator_mut().enumerate() {
        for (c, v) in row.iter_mut() {
            *v *= e[r / k] * e[c / k];
        }
    }
    t
}

/// The order the rows are integrated in, `k ↦ k·stride mod n`: a stride near `0.618 n`
/// coprime to `n`, so that the rows finished at any moment are spread over the whole mesh.
/// Rows differ in cost (facing pairs, partly hidden pairs and their rays cluster by
/// surface); spread, the pairs done measure the work done, and the progress's time left
/// (`crate::progress::time_left`) holds (issue 17, item 6).
pub fn row_stride(n: usize) -> usize {
    let gcd = |mut a: usize, mut b: usize| {
        while b != 0 {
            (a, b) = (b, a % b);
        }
        a
    };
    let mut stride = ((n as f64 * 0.618_033_988_75).round() as usize).max(1);
    while gcd(stride, n) > 1 {
        stride += 1;
    }
    stride
}

/// Row-sum mismatch up to which balancing counts as converged.
const BALANCED: f64 = 1e-9;
/// Largest row correction (`|D² − 1|`) accepted from balancing by cell.
const MOST_CORRECTION: f64 = 3.0;

/// The closure each row `(i,d)` must carry. A patch's closure is its base-rule closure
/// where that agrees with its adaptive row sum to `1e-3`, else the adaptive sum. With
/// `by_cell`, a patch that closes completely (to `1e-9`: nothing escapes from it) sees
/// the whole hemisphere covered, so each of its cells carries exactly `A_i μ_d/π`;
/// elsewhere (and always without `by_cell`) the patch's closure is shared among its cells
/// as the binning distributed it. Balancing by cell is tried first; where its targets
/// contradict each other (an enclosed patch that exchanges only with open ones, say) it
/// does not converge, and the kernel is balanced by patch instead (reported).
fn cell_targets(
    mesh: &Mesh,
    directions: &DirectionSet,
    work: &[RowWork],
    exchange: &CsMat<f64>,
    exposure: &[f64],
    by_cell: bool,
) -> Vec<f64> {
    let k = directions.len();
    let mut closure: Vec<f64> = work.iter().map(|w| w.closure).collect();
    for w in work {
        for p in &w.pairs {
            closure[p.j as usize] += p.base_j;
        }
    }
    closure.iter_mut().zip(exposure).for_each(|(c, e)| *c *= e);
    let row_sums: Vec<f64> = exchange.outer_iterator().map(|r| r.data().iter().sum()).collect();
    let mut targets = vec![0.0; row_sums.len()];
    for (i, patch) in mesh.patches.iter().enumerate() {
        let cells = &row_sums[i * k..(i + 1) * k];
        let adaptive: f64 = cells.iter().sum();
        let trusted = (closure[i] - adaptive).abs() <= TRUSTED_CLOSURE * adaptive;
        let total = if trusted { closure[i] } else { adaptive };
        let closed = by_cell && trusted && (closure[i] - patch.exposed).abs() <= 1e-9 * patch.area;
        for (c, target) in targets[i * k..(i + 1) * k].iter_mut().enumerate() {
            *target = if closed {
                patch.exposed * directions.cells()[c].projected / std::f64::consts::PI
            } else if adaptive > 0.0 {
                total * cells[c] / adaptive
            } else {
                0.0
            };
        }
    }
    targets
}

fn row_work(
    mesh: &Mesh,
    visibility: &Visibility,
    q: &Quadrature,
    binning: Option<&Binning>,
    points: &[[glam::DVec3; POINTS]],
    i: usize,
) -> RowWork {
    let a = &mesh.patches[i];
    let mut row = RowWork::default();
    let mut blocker = NO_BLOCKER;
    let (mut from_a, mut from_b) = (Vec::new(), Vec::new());
    for j in i + 1..mesh.len() {
        let b = &mesh.patches[j];
        if !facing(a, b) {
            continue;
        }
        let (ab, ba) = exchange(a, b, q, binning, &mut from_a, &mut from_b);
        if ab.adaptive <= 0.0 && ba.adaptive <= 0.0 {
            continue;
        }
        row.visited += 1;
        let visible = visible_fraction(visibility, a, &points[i], b, &points[j], &mut blocker);
        row.rays += visible.rays;
        let v = visible.fraction;
        if v <= 0.0 {
            continue;
        }
        let first = row.cells.len() as u32;
        push_pieces((ab, ba), &from_a, &from_b, binning, v, &mut row.cells);
        let count = row.cells.len() as u32 - first;
        row.pairs.push(Pair { j: j as u32, first, count, base_j: ba.base * v });
        row.closure += ab.base * v;
    }
    row
}
