//! The three goniometric systems of photometric files (CIE 121; IES LM-63 types A, B, C)
//! as one spherical coordinate system each, in the luminaire frame.
//!
//! The luminaire frame: `x` along the luminaire's length (the C0 axis), `y` across it
//! (C90), `z` up, so the nadir `−z` is the aiming direction (`γ = 0`). A table holds candela
//! over `(a, θ)`: `θ` the angle from the system's pole `p`, `a` the azimuth about it,
//! measured from `e0` towards `e90`, so that
//! `l = cosθ p + sinθ (cos a e0 + sin a e90)`:
//!
//! | system | pole `p` | `e0` | `e90` | file angles |
//! |---|---|---|---|---|
//! | C | `−z` (nadir) | `x` | `y` | `a = C` (horizontal), `θ = γ` (vertical) |
//! | B | `y` (the width axis) | `−z` | `x` | `a = H`, `θ = 90° − V` |
//! | A | `−x` (the length axis) | `−z` | `y` | `a = H`, `θ = 90° − V` |
//!
//! In type C, `C` turns counter-clockwise seen from above (from `x` towards `y`). Type B
//! planes `H` turn about the width axis (LM-63: "the polar axis coincides with the minor
//! axis"), `V` is the latitude towards it; this is the relation `tan H = cos C tan γ`,
//! `sin V = sin C sin γ` of the usual B-to-C conversion. Type A is type B turned by 90°
//! about the vertical axis (the polar axis is the length; IFC `IfcLightDistributionCurveEnum`).

use glam::DVec3;

/// A goniometric system: which pole and which azimuth origin the angles refer to.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum System {
    /// Type A: the pole along the length axis (`−x`).
    A,
    /// Type B: the pole along the width axis (`y`).
    B,
    /// Type C: the pole at the nadir (`−z`), the usual one.
    C,
}

impl System {
    /// `(p, e0, e90)` in the luminaire frame.
    fn axes(self) -> (DVec3, DVec3, DVec3) {
        match self {
            System::C => (DVec3::NEG_Z, DVec3::X, DVec3::Y),
            System::B => (DVec3::Y, DVec3::NEG_Z, DVec3::X),
            System::A => (DVec3::NEG_X, DVec3::NEG_Z, DVec3::Y),
        }
    }

    /// `(a, θ)` in degrees of a unit direction of the luminaire frame; `a ∈ (−180, 180]`.
    pub fn angles(self, l: DVec3) -> (f64, f64) {
        let (p, e0, e90) = self.axes();
        let theta = l.dot(p).clamp(-1.0, 1.0).acos().to_degrees();
        let a = l.dot(e90).atan2(l.dot(e0)).to_degrees();
        (a, theta)
    }

    /// The unit direction of the luminaire frame at `(a, θ)`, degrees.
    pub fn direction(self, a: f64, theta: f64) -> DVec3 {
        let (p, e0, e90) = self.axes();
        let (sa, ca) = a.to_radians().sin_cos();
        let (st, ct) = theta.to_radians().sin_cos();
        p * ct + (e0 * ca + e90 * sa) * st
    }
}
