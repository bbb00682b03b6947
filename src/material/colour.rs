//! The diffuse reflectance of a colour a model file gives a surface (a glTF material's base
//! colour): its luminance, `ρ = 0.2126 R + 0.7152 G + 0.0722 B` for linear Rec. 709 (sRGB)
//! primaries (ITU-R BT.709; the `Y` row of the sRGB-to-XYZ matrix), so that a grey of
//! value `g` reflects `g` and white reflects 1 (`docs/scene-format.md`, "mesh"); and the
//! linear value of an sRGB-encoded one (a texel of a base colour texture).

/// The luminance weights of linear red, green and blue; they sum to 1.
pub const LUMINANCE_WEIGHTS: [f64; 3] = [0.2126, 0.7152, 0.0722];

/// The reflectance of the linear colour `rgb` (each channel in [0, 1]): its luminance.
pub fn reflectance_of_colour(rgb: [f64; 3]) -> f64 {
    rgb.iter().zip(LUMINANCE_WEIGHTS).map(|(c, w)| c * w).sum()
}

/// The linear value of the sRGB-encoded `encoded` in [0, 1] (IEC 61966-2-1's transfer
/// function: `c / 12.92` up to 0.04045, `((c + 0.055) / 1.055)^2.4` above).
pub fn linear_of_srgb(encoded: f64) -> f64 {
    if encoded <= 0.040_45 { encoded / 12.92 } else { ((encoded + 0.055) / 1.055).powf(2.4) }
}
