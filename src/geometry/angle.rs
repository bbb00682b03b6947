//! The angle between two directions from its sine and cosine, `atan2(s, c)` for `s ≥ 0`:
//! the building block of Lambert's contour integral (`docs/design.md` (3.9),
//! `transfer/contour.rs`), which takes one per edge: the C library's `atan2` there was 13.7 %
//! of the office's samples (`docs/performance.md`, "The contour integral's angle"). Reduced
//! to `atan u` with `|u| ≤ tan(π/8)` and a polynomial there; within 5e-16 of `f64::atan2`
//! relative to the angle (`tests/geometry/angle.rs`).

use std::f64::consts::{FRAC_PI_2, FRAC_PI_4, PI};

/// `tan(π/8)`: below it `atan` is the polynomial, above it `π/4 + atan((t − 1)/(t + 1))`.
const TAN_PI_8: f64 = 0.414_213_562_373_095_03;

/// `(atan √z / √z − 1)/z` on `0 ≤ z ≤ tan²(π/8)` as a polynomial in `z`, lowest power first:
/// the Taylor series `Σ (−1)^k z^(k−1)/(2k+1)` economized by Chebyshev polynomials of
/// degree 10 in exact arithmetic (`docs/angle-fit.py`); truncation 5e-18 of `atan u`.
const ATAN: [f64; 11] = [
    -0.333_333_333_333_333_3,
    0.199_999_999_999_956_52,
    -0.142_857_142_846_913_8,
    0.111_111_110_171_003_27,
    -0.090_909_046_476_956_8,
    0.076_921_846_993_717_78,
    -0.066_645_313_698_050_09,
    0.058_583_118_105_011_53,
    -0.050_862_548_858_231_43,
    0.039_253_696_320_618_56,
    -0.019_202_529_268_412_274,
];

/// The angle in `[0, π]` whose sine and cosine are proportional to `sine ≥ 0` and
/// `cosine`: `sine.atan2(cosine)`; 0 when both are 0.
#[inline]
pub fn angle(sine: f64, cosine: f64) -> f64 {
    let along = cosine.abs();
    let steep = sine > along;
    let (small, large) = if steep { (along, sine) } else { (sine, along) };
    if large == 0.0 {
        return 0.0;
    }
    // ψ = atan(small/large) in [0, π/4]
    let psi = if small <= TAN_PI_8 * large {
        atan_near_zero(small / large)
    } else {
        FRAC_PI_4 + atan_near_zero((small - large) / (small + large))
    };
    let first_quadrant = if steep { FRAC_PI_2 - psi } else { psi };
    if cosine < 0.0 { PI - first_quadrant } else { first_quadrant }
}

/// `atan u` for `|u| ≤ tan(π/8)`. The polynomial by Estrin's scheme: its products in
/// pairs, so that the additions wait on four products in a row, not eleven (Horner's rule
/// took as long as the C library's `atan2`).
fn atan_near_zero(u: f64) -> f64 {
    let c = &ATAN;
    let z = u * u;
    let z2 = z * z;
    let z4 = z2 * z2;
    let pairs = [c[0] + c[1] * z, c[2] + c[3] * z, c[4] + c[5] * z, c[6] + c[7] * z, c[8] + c[9] * z];
    let quads = [pairs[0] + pairs[1] * z2, pairs[2] + pairs[3] * z2, pairs[4] + c[10] * z2];
    let p = quads[0] + quads[1] * z4 + quads[2] * (z4 * z4);
    u + u * z * p
}
