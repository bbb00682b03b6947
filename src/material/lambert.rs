//! Lambert: `ρ ≡ r`, so every cell average is `r` (reflection, or `τ` for transmission).

/// The `K × K` block of a constant luminance factor.
pub fn block(value: f64, k: usize) -> Vec<f64> {
    vec![value; k * k]
}
