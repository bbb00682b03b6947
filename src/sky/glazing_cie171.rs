//! CIE 171's clear glass (`glass = "cie171"`): the directional transmittance of 6 mm clear
//! float glass that CIE 171:2006 prescribes for its glazed daylight cases (test 5.5, its
//! "Eq. 19", after Tregenza 1987; Tregenza & Sharples, *Daylight Algorithms*, algorithm
//! 2.34), a polynomial in `c = cos θ`, the cosine of the incidence on the glass:
//!
//! `τ(c) = −0.028378 + 3.156075 c − 3.058376 c² − 1.428919 c³ + 4.014235 c⁴ − 1.775827 c⁵`
//!
//! `τ(1) = 0.87881` at normal incidence; the hemispherical (diffuse) transmittance
//! `2 ∫ τ(c) c dc` is 0.80562. The polynomial is negative below `c = 0.00907` (89.48°), where
//! it is taken as 0. It already includes both faces' reflections and the absorption: the
//! report's own model, applied direction by direction (`docs/daylight.md`).

/// `a₀ … a₅` of `τ(c) = Σ a_k c^k`.
pub const COEFFICIENTS: [f64; 6] = [-0.028378, 3.156075, -3.058376, -1.428919, 4.014235, -1.775827];

/// `τ(c)` for `cos` the cosine of the incidence on the glass (its sign ignored), at least 0.
pub fn transmittance(cos: f64) -> f64 {
    let c = cos.abs().min(1.0);
    COEFFICIENTS.iter().rev().fold(0.0, |sum, a| sum * c + a).max(0.0)
}
