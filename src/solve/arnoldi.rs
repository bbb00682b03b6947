//! The eigenvalues of largest magnitude of `K` and their eigenvectors (`docs/design.md` §4, the
//! spectrum that sets every iteration's rate), by thick-restart Arnoldi, matrix-free
//! through [`LinOp`] so that it runs on the factored and the hierarchical kernel alike.
//!
//! Arnoldi builds an orthonormal basis `V` (classical Gram–Schmidt, repeated once: DGKS)
//! with `K V_m = V_m H_m + β v_{m+1} e_mᵀ`. The Ritz pairs `(θ, V y)` come from the dense
//! eigen-decomposition of `H_m` (faer); the residual of a pair is `β |y_m|`. A restart keeps
//! a real orthonormal basis `Y` of the wanted Ritz vectors of `H_m` (real and imaginary parts
//! of a complex pair, never one half of a pair): `K (V Y) = (V Y)(Yᵀ H Y) + β v_{m+1}
//! e_mᵀ Y` is again a Krylov decomposition, which Arnoldi extends from `v_{m+1}`. This is
//! Stewart's Krylov–Schur restart with a Ritz basis in place of the Schur basis; with exact
//! shifts it spans the same space as Sorensen's implicit restart.
//!
//! A pair has converged when `‖K x − θ x‖ ≤ tolerance · |θ₁|` (`x` of unit norm, `θ₁` the
//! largest Ritz value); the eigen-residuals reported are recomputed with `K` itself.

use super::LinOp;
use super::outcome::{dot, norm};
use crate::random::Rng;
use faer::Mat;
use thiserror::Error;

/// What to compute.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ArnoldiParams {
    /// Eigenvalues wanted, the largest in magnitude.
    pub count: usize,
    /// Basis size `m` between restarts (0: `max(2·count + 1, count + 20)`, at most `dim`).
    pub subspace: usize,
    /// Eigen-residual relative to `|θ₁|` below which a pair has converged.
    pub tolerance: f64,
    /// Most restarts before giving up (the pairs found so far are returned, marked).
    pub max_restarts: usize,
}

impl ArnoldiParams {
    /// `count` eigenvalues to 1e-10 with the default basis size.
    pub fn largest(count: usize) -> ArnoldiParams {
        ArnoldiParams { count, subspace: 0, tolerance: 1e-10, max_restarts: 500 }
    }
}

/// An eigenvalue `λ = re + i·im` and its eigenvector `x = vector_re + i·vector_im`.
#[derive(Debug, Clone, PartialEq)]
pub struct Eigenpair {
    /// Real part of the eigenvalue.
    pub re: f64,
    /// Imaginary part of the eigenvalue.
    pub im: f64,
    /// Real part of the eigenvector, scaled so that `max |x_i| = 1` at a real positive entry.
    pub vector_re: Vec<f64>,
    /// Imaginary part (zero for a real eigenvalue).
    pub vector_im: Vec<f64>,
    /// `‖K x − λ x‖₂ / ‖x‖₂`, recomputed with the operator.
    pub residual: f64,
}

impl Eigenpair {
    /// `|λ|`.
    pub fn magnitude(&self) -> f64 {
        self.re.hypot(self.im)
    }
}

/// The leading part of the spectrum, largest magnitude first.
#[derive(Debug, Clone, PartialEq)]
pub struct Spectrum {
    /// The eigenpairs found, largest magnitude first.
    pub pairs: Vec<Eigenpair>,
    /// Thick restarts of the Arnoldi basis.
    pub restarts: usize,
    /// Products with `K`.
    pub applications: usize,
    /// Whether every wanted pair met the tolerance.
    pub converged: bool,
    /// Tolerance on `‖K x − θ x‖` relative to `|θ₁|`.
    pub tolerance: f64,
    /// Wall time, s.
    pub seconds: f64,
}

/// Why no spectrum was computed.
#[derive(Debug, Error, PartialEq)]
pub enum ArnoldiError {
    /// More eigenvalues asked for than `K` has, or none.
    #[error("--spectrum N asks for 1 to {dim} eigenvalues (the unknowns of K), got {count}")]
    Count {
        /// Eigenvalues asked for.
        count: usize,
        /// Unknowns of `K`.
        dim: usize,
    },
    /// The dense eigen-decomposition of the Arnoldi matrix failed.
    #[error("the dense eigen-decomposition of the {m}×{m} Arnoldi matrix failed: {why}")]
    Dense {
        /// Size of the Arnoldi matrix.
        m: usize,
        /// What failed.
        why: String,
    },
    /// The operator produced a NaN or infinite value.
    #[error("the operator gave a non-finite value: K has NaN or infinite entries")]
    NotFinite,
    /// A signal asked the process to stop.
    #[error(transparent)]
    Interrupted(#[from] crate::interrupt::Interrupted),
}

/// A Ritz value `θ` and the eigenvector `y` of `H_m` it comes from.
struct Ritz {
    re: f64,
    im: f64,
    y_re: Vec<f64>,
    y_im: Vec<f64>,
}

/// The `params.count` eigenvalues of `k` of largest magnitude and their eigenvectors.
pub fn arnoldi(k: &dyn LinOp, params: &ArnoldiParams) -> Result<Spectrum, ArnoldiError> {
    let start = std::time::Instant::now();
    let (n, count) = (k.dim(), params.count);
    if count == 0 || count > n {
        return Err(ArnoldiError::Count { count, dim: n });
    }
    let wanted = if params.subspace > 0 { params.subspace } else { (2 * count + 1).max(count + 20) };
    let m = wanted.max(count + 2).min(n);
    let mut basis = Krylov { v: vec![random_unit(n, 0)], h: vec![vec![0.0; m]; m + 1], applications: 0, breakdowns: 0 };
    let mut kept = 0;
    let mut restarts = 0;
    loop {
        for j in kept..m {
            crate::interrupt::check(|| format!("the Arnoldi iteration of the spectrum (restart {restarts})"))?;
            basis.extend(k, j)?;
        }
        let beta = basis.h[m][m - 1];
        let ritz = ritz_pairs(&basis.h, m)?;
        let scale = ritz[0].re.hypot(ritz[0].im).max(f64::MIN_POSITIVE);
        let residual = |r: &Ritz| beta.abs() * r.y_re[m - 1].hypot(r.y_im[m - 1]);
        let converged = ritz[..count].iter().all(|r| residual(r) <= params.tolerance * scale);
        if converged || restarts == params.max_restarts || m == n {
            let pairs = ritz[..count].iter().map(|r| basis.pair(k, r, m)).collect::<Result<_, _>>()?;
            let seconds = start.elapsed().as_secs_f64();
            let applications = basis.applications;
            return Ok(Spectrum { pairs, restarts, applications, converged, tolerance: params.tolerance, seconds });
        }
        kept = basis.restart(&ritz, keep(&ritz, count, m), m);
        restarts += 1;
    }
}

/// Ritz vectors kept at a restart (`m ≥ count + 2`): halfway between `count` and `m`, one
/// more or one fewer rather than half of a complex pair, always at least `count` and fewer than `m`.
fn keep(ritz: &[Ritz], count: usize, m: usize) -> usize {
    let keep = count + (m - count) / 2;
    let splits = ritz[keep - 1].im > 0.0 && ritz[keep - 1].im == -ritz[keep].im;
    match (splits, keep + 1 < m) {
        (false, _) => keep,
        (true, true) => keep + 1,
        (true, false) => keep - 1,
    }
}

/// The eigen-decomposition of the leading `m × m` block of `h`, largest magnitude first
/// (conjugate pairs side by side, the positive imaginary part first), eigenvectors of unit norm.
fn ritz_pairs(h: &[Vec<f64>], m: usize) -> Result<Vec<Ritz>, ArnoldiError> {
    let dense = Mat::<f64>::from_fn(m, m, |i, j| h[i][j]);
    let eigen = dense.eigen().map_err(|e| ArnoldiError::Dense { m, why: format!("{e:?}") })?;
    let (u, s) = (eigen.U(), eigen.S().column_vector());
    let mut ritz: Vec<Ritz> = (0..m)
        .map(|c| {
            let length = (0..m).map(|i| u[(i, c)].re.powi(2) + u[(i, c)].im.powi(2)).sum::<f64>().sqrt();
            let length = if length > 0.0 { length } else { 1.0 };
            Ritz {
                re: s[c].re,
                im: s[c].im,
                y_re: (0..m).map(|i| u[(i, c)].re / length).collect(),
                y_im: (0..m).map(|i| u[(i, c)].im / length).collect(),
            }
        })
        .collect();
    if ritz.iter().any(|r| !(r.re.is_finite() && r.im.is_finite())) {
        return Err(ArnoldiError::NotFinite);
    }
    ritz.sort_by(|a, b| {
        let magnitude = |r: &Ritz| r.re.hypot(r.im);
        magnitude(b).total_cmp(&magnitude(a)).then(b.re.total_cmp(&a.re)).then(b.im.total_cmp(&a.im))
    });
    Ok(ritz)
}

/// The Krylov decomposition `K V_m = V_{m+1} H`.
struct Krylov {
    /// `v_0 … v_j`, orthonormal.
    v: Vec<Vec<f64>>,
    /// `(m + 1) × m`, row-major.
    h: Vec<Vec<f64>>,
    applications: usize,
    /// Invariant subspaces met so far (each continued from a new random vector).
    breakdowns: u64,
}

/// Below this fraction of `‖K v_j‖` the new direction is taken as round-off: the basis
/// spans an invariant subspace.
const BREAKDOWN: f64 = 1e-12;

impl Krylov {
    /// Column `j`: `v_{j+1}` from `K v_j`.
    fn extend(&mut self, k: &dyn LinOp, j: usize) -> Result<(), ArnoldiError> {
        let n = self.v[0].len();
        let mut w = vec![0.0; n];
        k.apply(&self.v[j], &mut w);
        self.applications += 1;
        let before = norm(&w);
        if !before.is_finite() {
            return Err(ArnoldiError::NotFinite);
        }
        let coefficients = orthogonalize(&self.v[..=j], &mut w);
        self.v.truncate(j + 1);
        for (i, c) in coefficients.into_iter().enumerate() {
            self.h[i][j] = c;
        }
        let beta = norm(&w);
        let m = self.h[0].len();
        if beta > BREAKDOWN * before {
            self.h[j + 1][j] = beta;
            self.v.push(w.into_iter().map(|x| x / beta).collect());
        } else if j + 1 < m {
            // An invariant subspace: go on from a random direction orthogonal to it.
            self.h[j + 1][j] = 0.0;
            self.breakdowns += 1;
            let mut r = random_unit(n, self.breakdowns);
            orthogonalize(&self.v, &mut r);
            let length = norm(&r);
            self.v.push(r.into_iter().map(|x| x / length).collect());
        } else {
            self.h[j + 1][j] = 0.0;
            self.v.push(vec![0.0; n]);
        }
        Ok(())
    }

    /// Keeps the span of the first `keep` Ritz vectors (never half of a complex pair) and
    /// `v_{m+1}`; returns the number of basis vectors kept before `v_{m+1}`.
    fn restart(&mut self, ritz: &[Ritz], keep: usize, m: usize) -> usize {
        let mut columns: Vec<Vec<f64>> = Vec::with_capacity(keep + 1);
        for r in &ritz[..keep] {
            if r.im < 0.0 {
                continue; // the conjugate's real and imaginary parts are in already
            }
            columns.push(r.y_re.clone());
            if r.im != 0.0 {
                columns.push(r.y_im.clone());
            }
        }
        let mut y: Vec<Vec<f64>> = Vec::new();
        for mut c in columns {
            orthogonalize(&y, &mut c);
            let length = norm(&c);
            if length > 1e-10 {
                y.push(c.into_iter().map(|x| x / length).collect());
            }
        }
        let p = y.len();
        let beta = self.h[m][m - 1];
        let hy: Vec<Vec<f64>> = y.iter().map(|c| (0..m).map(|i| dot(&self.h[i][..m], c)).collect()).collect();
        let mut h = vec![vec![0.0; m]; m + 1];
        for (a, ya) in y.iter().enumerate() {
            for (b, hb) in hy.iter().enumerate() {
                h[a][b] = dot(ya, hb);
            }
        }
        for (b, yb) in y.iter().enumerate() {
            h[p][b] = beta * yb[m - 1];
        }
        let next = self.v[m].clone();
        let mut v: Vec<Vec<f64>> = y.iter().map(|c| combine(&self.v[..m], c)).collect();
        v.push(next);
        self.v = v;
        self.h = h;
        p
    }

    /// The eigenpair of Ritz value `r`: `x = V_m y`, scaled, with its true residual.
    fn pair(&mut self, k: &dyn LinOp, r: &Ritz, m: usize) -> Result<Eigenpair, ArnoldiError> {
        let (mut xr, mut xi) = (combine(&self.v[..m], &r.y_re), combine(&self.v[..m], &r.y_im));
        if r.im == 0.0 {
            xi.iter_mut().for_each(|x| *x = 0.0);
        }
        let top = (0..xr.len()).max_by(|&a, &b| xr[a].hypot(xi[a]).total_cmp(&xr[b].hypot(xi[b]))).unwrap_or(0);
        let (pr, pi, length) = (xr[top], xi[top], xr[top].hypot(xi[top]).max(f64::MIN_POSITIVE));
        // x ← x · conj(x_top) / |x_top|²: entry `top` becomes 1.
        for (a, b) in xr.iter_mut().zip(xi.iter_mut()) {
            let (re, im) = (*a * pr + *b * pi, *b * pr - *a * pi);
            (*a, *b) = (re / (length * length), im / (length * length));
        }
        let (mut kr, mut ki) = (vec![0.0; xr.len()], vec![0.0; xr.len()]);
        k.apply(&xr, &mut kr);
        k.apply(&xi, &mut ki);
        self.applications += 2;
        let mut squared = 0.0;
        for i in 0..xr.len() {
            let re = kr[i] - (r.re * xr[i] - r.im * xi[i]);
            let im = ki[i] - (r.re * xi[i] + r.im * xr[i]);
            squared += re * re + im * im;
        }
        let length = (dot(&xr, &xr) + dot(&xi, &xi)).sqrt();
        let residual = squared.sqrt() / length;
        Ok(Eigenpair { re: r.re, im: r.im, vector_re: xr, vector_im: xi, residual })
    }
}

/// Removes from `w` its components along the orthonormal `basis`, twice (DGKS); returns
/// the coefficients removed.
fn orthogonalize(basis: &[Vec<f64>], w: &mut [f64]) -> Vec<f64> {
    let mut total = vec![0.0; basis.len()];
    for _ in 0..2 {
        let c: Vec<f64> = basis.iter().map(|b| dot(b, w)).collect();
        for (b, ci) in basis.iter().zip(&c) {
            w.iter_mut().zip(b).for_each(|(x, bi)| *x -= ci * bi);
        }
        total.iter_mut().zip(&c).for_each(|(t, ci)| *t += ci);
    }
    total
}

/// `Σ_j c_j v_j`.
fn combine(v: &[Vec<f64>], c: &[f64]) -> Vec<f64> {
    let mut out = vec![0.0; v[0].len()];
    for (vj, cj) in v.iter().zip(c) {
        out.iter_mut().zip(vj).for_each(|(o, x)| *o += cj * x);
    }
    out
}

/// A reproducible random unit vector (entries in `[0.5, 1.5)`, so the Perron vector is
/// never missed), stream `index`.
fn random_unit(n: usize, index: u64) -> Vec<f64> {
    let mut rng = Rng::stream(0x5EC7_0000, index);
    let v: Vec<f64> = (0..n).map(|_| 0.5 + rng.uniform()).collect();
    let length = norm(&v);
    v.into_iter().map(|x| x / length).collect()
}
