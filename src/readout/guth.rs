//! The Guth position index `p` of CIE 117:1995 (`docs/photometry.md`, "UGR"): how much less
//! a glare source troubles the eye the farther it lies from the line of sight. Luckiesh
//! and Guth (1949) tabulated it; this is the closed form fitted to their table that
//! Radiance's `glarendx.cal` and evalglare use,
//!
//! `p = exp((35.2 − 0.31889 τ − 1.22 e^(−2τ/9)) 10⁻³ σ + (21 + 0.26667 τ − 0.002963 τ²) 10⁻⁵ σ²)`,
//!
//! with `σ` the angle between the line of sight and the direction to the source and `τ`
//! the angle between the vertical and the plane through the line of sight and the source
//! (both in degrees); `p = 1` on the line of sight. Defined for sources above the line of
//! sight (CIE 117 counts only those), that is `0 ≤ τ < 90°`.

use glam::DVec3;

/// The position index of a source in the unit direction `towards` from an eye looking along
/// the unit `look` (not vertical); `None` when the source is not in front of the eye above
/// its line of sight (the plane through the line of sight and the horizontal across it).
pub fn position_index(look: DVec3, towards: DVec3) -> Option<f64> {
    let across = look.cross(DVec3::Y).normalize();
    let up = across.cross(look);
    let (x, y, z) = (towards.dot(across), towards.dot(up), towards.dot(look));
    if y <= 0.0 || z <= 0.0 {
        return None;
    }
    let sigma = z.clamp(-1.0, 1.0).acos().to_degrees();
    let tau = x.abs().atan2(y).to_degrees();
    let linear = (35.2 - 0.31889 * tau - 1.22 * (-2.0 * tau / 9.0).exp()) * 1e-3;
    let quadratic = (21.0 + 0.26667 * tau - 0.002963 * tau * tau) * 1e-5;
    Some((linear * sigma + quadratic * sigma * sigma).exp())
}
