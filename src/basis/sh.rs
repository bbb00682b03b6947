//! Real spherical harmonics `Y_n`, `n = l² + l + m`, and the hemispherical harmonics built
//! from them (`docs/design.md` §4, kernel factorization; conventions of `docs/references.md`).
//!
//! `Y_l0 = K_l^0 P_l^0(cosθ)`, `Y_lm = √2 K_l^m P_l^m(cosθ) cos(mφ)` and
//! `Y_l,−m = √2 K_l^m P_l^m(cosθ) sin(mφ)` for `m > 0`, `K_l^m = √((2l+1)(l−m)!/(4π(l+m)!))`,
//! without the Condon–Shortley phase. The normalized Legendre functions `K_l^m P_l^m` come
//! from the stable three-term recurrence in `l` (no factorials, no cancellation), so any
//! `l_max` the direction sets can use is safe.
//!
//! Hemispherical harmonics (Gautron et al., EGSR 2004): `H_n(θ, φ) = √2 Y_n(θ̃, φ)` with
//! `cos θ̃ = 2 cosθ − 1`, orthonormal over the upper hemisphere with `dω`.

use std::f64::consts::{PI, SQRT_2};

/// Number of functions up to degree `lmax`: `(lmax + 1)²`.
pub fn count(lmax: usize) -> usize {
    (lmax + 1) * (lmax + 1)
}

/// Index `n` of `Y_lm`.
pub fn index(l: usize, m: i64) -> usize {
    ((l * l + l) as i64 + m) as usize
}

/// Writes `Y_n(θ, φ)` for `n < (lmax+1)²` into `out`, given `z = cosθ`.
pub fn real_sh(lmax: usize, z: f64, phi: f64, out: &mut [f64]) {
    let z = z.clamp(-1.0, 1.0);
    let s = (1.0 - z * z).max(0.0).sqrt();
    // The normalized K_m^m P_m^m, carried from m to m + 1.
    let mut p_mm = 0.5 / PI.sqrt();
    for m in 0..=lmax {
        if m > 0 {
            p_mm *= ((2 * m + 1) as f64 / (2 * m) as f64).sqrt() * s;
        }
        let (sin, cos) = (m as f64 * phi).sin_cos();
        let mut put = |l: usize, p: f64| {
            if m == 0 {
                out[index(l, 0)] = p;
            } else {
                out[index(l, m as i64)] = SQRT_2 * p * cos;
                out[index(l, -(m as i64))] = SQRT_2 * p * sin;
            }
        };
        put(m, p_mm);
        if m == lmax {
            break;
        }
        let mut before = p_mm;
        let mut p = (2.0 * m as f64 + 3.0).sqrt() * z * p_mm;
        put(m + 1, p);
        for l in m + 2..=lmax {
            let (lf, mf) = (l as f64, m as f64);
            let a = ((4.0 * lf * lf - 1.0) / (lf * lf - mf * mf)).sqrt();
            let b = (((lf - 1.0) * (lf - 1.0) - mf * mf) / (4.0 * (lf - 1.0) * (lf - 1.0) - 1.0)).sqrt();
            let next = a * (z * p - b * before);
            (before, p) = (p, next);
            put(l, p);
        }
    }
}

/// Writes the hemispherical harmonics `H_n(θ, φ)`, `n < (lmax+1)²`, given `z = cosθ ≥ 0`.
pub fn hemispherical(lmax: usize, z: f64, phi: f64, out: &mut [f64]) {
    real_sh(lmax, 2.0 * z - 1.0, phi, out);
    out[..count(lmax)].iter_mut().for_each(|v| *v *= SQRT_2);
}
