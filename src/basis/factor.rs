//! Low-rank factorizations of the material blocks, `ρ̄ ≈ Ψ Φᵀ` (`docs/design.md` §4, kernel
//! factorization): with them the outgoing luminance of a patch is `L = L0 + Ψ c`, and
//! its `M` coefficients `c` obey `c = Φᵀ G (L0 + Ψ c)`, so the kernel
//! `K(x', x) = Σ_n ψ_n(x) φ_n(x')` becomes a system of `N·M` unknowns (`reduced.rs`).
//!
//! * **SH**: `Ψ = E`, the cell averages of the `M = (l_max+1)²` hemispherical harmonics
//!   (full spherical harmonics on a sphere set); `Φ = E Rᵀ` with the material in the basis
//!   `R = P ρ̄ Pᵀ`, `P = (EᵀWE)⁺EᵀW` the least-squares projection with the cell solid
//!   angles `W`. Then `ρ̄ ≈ E R Eᵀ`, i.e. `ρ(l, l') ≈ Σ Y_n(l) R_nn' Y_n'(l')`, exact
//!   for a Lambertian material at `l_max = 0` and for any material once `M = K`.
//! * **SVD**: the truncated singular value decomposition of the block as an operator from
//!   incoming luminance to outgoing luminance, both in `L²(dω)`:
//!   `A = W^½ ρ̄ D W^-½` (`D = diag(μ_d/π)` turns a mean incoming luminance into the
//!   arriving `I_d`), `A ≈ U_R Σ_R V_Rᵀ`, `Ψ = W^-½ U_R`, `Φ = D⁻¹ W^½ V_R Σ_R`: the best
//!   rank-`R` approximation (Eckart–Young) in that norm.
//!
//! A transmitting material has a second `Φ` for the light arriving at its back (the SVD
//! factors `[ρ̄ | τ̄]` together, so both share `Ψ`).

use super::sh;
use crate::directions::DirectionSet;
use crate::material::Block;
use nalgebra::DMatrix;
use std::f64::consts::PI;
use thiserror::Error;

/// The angular basis of a reduced solve.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Basis {
    /// Hemispherical (or, on a sphere set, spherical) harmonics up to degree `lmax`.
    Sh {
        /// The highest degree `l`.
        lmax: usize,
    },
    /// The truncated SVD of each material block, rank `rank`.
    Svd {
        /// The rank kept.
        rank: usize,
    },
}

impl Basis {
    /// `sh:L` or `svd:R`.
    pub fn parse(text: &str) -> Option<Basis> {
        let (kind, order) = text.split_once(':')?;
        let order = order.parse().ok()?;
        match kind {
            "sh" => Some(Basis::Sh { lmax: order }),
            "svd" if order >= 1 => Some(Basis::Svd { rank: order }),
            _ => None,
        }
    }

    /// The basis as `--basis` names it: `sh:L` or `svd:R`.
    pub fn name(&self) -> String {
        match self {
            Basis::Sh { lmax } => format!("sh:{lmax}"),
            Basis::Svd { rank } => format!("svd:{rank}"),
        }
    }

    /// Coefficients per patch, `M`.
    pub fn size(&self) -> usize {
        match *self {
            Basis::Sh { lmax } => sh::count(lmax),
            Basis::Svd { rank } => rank,
        }
    }
}

/// Why a basis cannot be used on a direction set.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum BasisError {
    /// The basis has more coefficients per patch than the direction set has cells.
    #[error(
        "{basis} has {m} coefficients per patch but the direction set has only {k} cells; \
         use at most {k} (sh:L needs (L+1)² ≤ K)"
    )]
    TooLarge {
        /// The basis, as `--basis` names it.
        basis: String,
        /// Its coefficients per patch.
        m: usize,
        /// The direction set's cells.
        k: usize,
    },
}

/// `Ψ` and `Φ` of one material, `K × M`, row-major.
#[derive(Debug, Clone, PartialEq)]
pub struct MaterialFactor {
    /// `Ψ`: the basis functions on the cells, `K × M`, row-major.
    pub psi: Vec<f64>,
    /// For light arriving at the patch itself.
    pub front: Vec<f64>,
    /// For light arriving at its back-to-back twin (transmitters only).
    pub back: Option<Vec<f64>>,
}

/// The factorization of every material block of a kernel.
#[derive(Debug, Clone, PartialEq)]
pub struct Factorization {
    /// The basis factored in.
    pub basis: Basis,
    /// Coefficients per patch.
    pub m: usize,
    /// Direction cells.
    pub k: usize,
    /// Rank of the harmonics on the cells (SH: below `m` when a ring has too few cells
    /// for the highest azimuthal orders; the projection then drops the dependent part).
    pub rank: usize,
    /// By material index.
    pub materials: Vec<MaterialFactor>,
}

impl Factorization {
    /// Factors every block of `blocks` on `directions` in `basis`; refused when the basis has
    /// more coefficients than the set has cells.
    pub fn new(basis: Basis, blocks: &[Block], directions: &DirectionSet) -> Result<Factorization, BasisError> {
        let (m, k) = (basis.size(), directions.len());
        if m > k {
            return Err(BasisError::TooLarge { basis: basis.name(), m, k });
        }
        let mut rank = m;
        let materials = match basis {
            Basis::Sh { lmax } => {
                let e = cell_averages(lmax, directions);
                let (p, r) = projection(&e, directions);
                rank = r;
                blocks
                    .iter()
                    .map(|b| {
                        let in_basis = |values: &[f64]| {
                            &e * (&p * DMatrix::from_row_slice(k, k, values) * p.transpose()).transpose()
                        };
                        MaterialFactor {
                            psi: row_major(&e),
                            front: row_major(&in_basis(b.values())),
                            back: b.transmit_values().map(|t| row_major(&in_basis(t))),
                        }
                    })
                    .collect()
            }
            Basis::Svd { rank } => blocks.iter().map(|b| truncated_svd(b, directions, rank)).collect(),
        };
        Ok(Factorization { basis, m, k, rank, materials })
    }
}

/// `E[k, n]`: the mean of harmonic `n` over cell `k` (8 × 8 midpoints, uniform in `cosθ`
/// and `φ`, i.e. in solid angle). Cells of the lower half of a sphere set mirror the upper.
fn cell_averages(lmax: usize, directions: &DirectionSet) -> DMatrix<f64> {
    const SUB: usize = 8;
    let (k, m) = (directions.len(), sh::count(lmax));
    let mut e = DMatrix::zeros(k, m);
    let mut y = vec![0.0; m];
    for cell in 0..k {
        let (z0, z1, p0, p1) = directions.bounds(cell);
        let lower = directions.is_sphere() && cell >= k / 2;
        for a in 0..SUB {
            for b in 0..SUB {
                let z = z0 + (z1 - z0) * (a as f64 + 0.5) / SUB as f64;
                let phi = p0 + (p1 - p0) * (b as f64 + 0.5) / SUB as f64;
                if directions.is_sphere() {
                    sh::real_sh(lmax, if lower { -z } else { z }, phi, &mut y);
                } else {
                    sh::hemispherical(lmax, z, phi, &mut y);
                }
                for n in 0..m {
                    e[(cell, n)] += y[n] / (SUB * SUB) as f64;
                }
            }
        }
    }
    e
}

/// `P = (W^½E)⁺ W^½` (the least-squares projection, `(EᵀWE)⁻¹EᵀW` at full rank) and the
/// numerical rank of `W^½E` (singular values above `1e-9` of the largest).
fn projection(e: &DMatrix<f64>, directions: &DirectionSet) -> (DMatrix<f64>, usize) {
    let root: Vec<f64> = directions.cells().iter().map(|c| c.solid_angle.sqrt()).collect();
    let weighted = DMatrix::from_fn(e.nrows(), e.ncols(), |r, c| root[r] * e[(r, c)]);
    let svd = weighted.svd(true, true);
    let cut = 1e-9 * svd.singular_values.max();
    let rank = svd.singular_values.iter().filter(|&&s| s > cut).count();
    let pinv = svd.pseudo_inverse(cut).expect("u and vᵀ were computed");
    (DMatrix::from_fn(e.ncols(), e.nrows(), |r, c| pinv[(r, c)] * root[c]), rank)
}

/// The rank-`rank` SVD factors of `[ρ̄ | τ̄]` in the `L²(dω)` norms (module docs).
fn truncated_svd(block: &Block, directions: &DirectionSet, rank: usize) -> MaterialFactor {
    let k = directions.len();
    let cells = directions.cells();
    let w: Vec<f64> = cells.iter().map(|c| c.solid_angle.sqrt()).collect();
    let d: Vec<f64> = cells.iter().map(|c| c.projected / PI).collect();
    let parts: Vec<&[f64]> = std::iter::once(block.values()).chain(block.transmit_values()).collect();
    let a = DMatrix::from_fn(k, k * parts.len(), |r, c| {
        let (part, col) = (c / k, c % k);
        w[r] * parts[part][r * k + col] * d[col] / w[col]
    });
    let svd = a.svd(true, true);
    let (u, v_t, sigma) = (svd.u.expect("u requested"), svd.v_t.expect("vᵀ requested"), svd.singular_values);
    let mut order: Vec<usize> = (0..sigma.len()).collect();
    order.sort_by(|&x, &y| sigma[y].total_cmp(&sigma[x]));
    let psi = DMatrix::from_fn(k, rank, |r, n| u[(r, order[n])] / w[r]);
    let phi = |part: usize| {
        let m = DMatrix::from_fn(k, rank, |col, n| w[col] / d[col] * v_t[(order[n], part * k + col)] * sigma[order[n]]);
        row_major(&m)
    };
    MaterialFactor { psi: row_major(&psi), front: phi(0), back: (parts.len() > 1).then(|| phi(1)) }
}

fn row_major(m: &DMatrix<f64>) -> Vec<f64> {
    (0..m.nrows()).flat_map(|r| (0..m.ncols()).map(move |c| m[(r, c)])).collect()
}
