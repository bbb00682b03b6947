//! The luminous opening of a luminaire: the part of it that shines, as its photometric file
//! sizes it, centred on the photometric centre in the luminaire frame (`x` along C0, `y`
//! along C90, `z` up). It does not change the light a luminaire sends (a point source,
//! `docs/design.md` §1); it is what the eye sees of the luminaire, at the luminance
//! `L(l) = I(l) / A_p(l)` with `A_p` the opening's area projected on a plane normal to `l`
//! (`docs/photometry.md`, the luminous opening).
//!
//! * IES LM-63: width (along C90), length (along C0) and height, in feet or metres by the
//!   units type. All three zero: no opening; width and length negative: a vertical
//!   cylinder of that diameter (a disc when the height is 0); all three negative: a sphere;
//!   otherwise a box (a rectangle when the height is 0).
//! * EULUMDAT: the luminous area's length (along C0) and width (along C90), mm; a width of
//!   0 is a disc of diameter the length; its height is the mean of the four heights given
//!   at C0, C90, C180 and C270.
//! * A luminaire without an opening (a closed-form distribution, a file of zero sizes) is
//!   drawn as a sphere of [`FALLBACK_DIAMETER`].

use glam::DVec3;
use std::f64::consts::PI;

/// The diameter of the sphere drawn for a luminaire whose file gives no luminous opening, m.
pub const FALLBACK_DIAMETER: f64 = 0.1;

/// The shining part of a luminaire, in its frame, m.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum LuminousOpening {
    /// A box `length × width × height` along `x`, `y`, `z` (a rectangle when `height` is 0).
    Box {
        /// Along C0 (`x`), m.
        length: f64,
        /// Along C90 (`y`), m.
        width: f64,
        /// Along the up axis (`z`), m.
        height: f64,
    },
    /// A cylinder about the `z` axis (a disc when `height` is 0).
    Cylinder {
        /// m.
        diameter: f64,
        /// m.
        height: f64,
    },
    /// A sphere.
    Sphere {
        /// m.
        diameter: f64,
    },
}

impl LuminousOpening {
    /// The opening of an IES file's `width`, `length`, `height`, already in metres; `None`
    /// when all three are 0.
    pub fn of_ies(width: f64, length: f64, height: f64) -> Option<LuminousOpening> {
        let (w, l, h) = (width.abs(), length.abs(), height.abs());
        match (width < 0.0, length < 0.0, height < 0.0) {
            _ if w == 0.0 && l == 0.0 && h == 0.0 => None,
            (true, true, true) => Some(LuminousOpening::Sphere { diameter: w }),
            (true, true, false) => Some(LuminousOpening::Cylinder { diameter: w, height: h }),
            _ => Some(LuminousOpening::Box { length: l, width: w, height: h }),
        }
    }

    /// The opening of an EULUMDAT file's luminous area, metres; `None` when its length is 0.
    pub fn of_ldt(length: f64, width: f64, height: f64) -> Option<LuminousOpening> {
        match (length > 0.0, width > 0.0) {
            (false, _) => None,
            (true, false) => Some(LuminousOpening::Cylinder { diameter: length, height: height.max(0.0) }),
            (true, true) => Some(LuminousOpening::Box { length, width, height: height.max(0.0) }),
        }
    }

    /// The area seen from the unit direction `l` of the luminaire frame, m².
    pub fn projected_area(&self, l: DVec3) -> f64 {
        match *self {
            LuminousOpening::Box { length, width, height } => {
                length * width * l.z.abs() + width * height * l.x.abs() + length * height * l.y.abs()
            }
            LuminousOpening::Cylinder { diameter, height } => {
                PI * diameter * diameter / 4.0 * l.z.abs() + diameter * height * (1.0 - l.z * l.z).max(0.0).sqrt()
            }
            LuminousOpening::Sphere { diameter } => PI * diameter * diameter / 4.0,
        }
    }

    /// The distance along the ray `origin + t·direction` (luminaire frame, relative to the
    /// photometric centre) at which it meets the opening, if it does ahead of `origin`.
    pub fn entry(&self, origin: DVec3, direction: DVec3) -> Option<f64> {
        let (near, far) = match *self {
            LuminousOpening::Box { length, width, height } => {
                let half = DVec3::new(length, width, height) / 2.0;
                (0..3).try_fold((f64::NEG_INFINITY, f64::INFINITY), |span, k| {
                    overlap(span, slab(origin[k], direction[k], half[k])?)
                })?
            }
            LuminousOpening::Cylinder { diameter, height } => {
                let flat = DVec3::new(1.0, 1.0, 0.0);
                let round = ball(origin * flat, direction * flat, diameter / 2.0)?;
                overlap(round, slab(origin.z, direction.z, height / 2.0)?)?
            }
            LuminousOpening::Sphere { diameter } => ball(origin, direction, diameter / 2.0)?,
        };
        (far >= 0.0).then_some(near.max(0.0))
    }
}

/// The common part of two spans of the ray, if any.
fn overlap((a0, a1): (f64, f64), (b0, b1): (f64, f64)) -> Option<(f64, f64)> {
    let span = (a0.max(b0), a1.min(b1));
    (span.0 <= span.1).then_some(span)
}

/// The span of `t` for which `|o + t·d| ≤ half` along one axis.
fn slab(o: f64, d: f64, half: f64) -> Option<(f64, f64)> {
    if d == 0.0 {
        return (o.abs() <= half).then_some((f64::NEG_INFINITY, f64::INFINITY));
    }
    let (a, b) = ((-half - o) / d, (half - o) / d);
    Some((a.min(b), a.max(b)))
}

/// The span of `t` for which `|o + t·d| ≤ radius` (the components left in `o` and `d`).
fn ball(o: DVec3, d: DVec3, radius: f64) -> Option<(f64, f64)> {
    let (a, b, c) = (d.length_squared(), o.dot(d), o.length_squared() - radius * radius);
    if a == 0.0 {
        return (c <= 0.0).then_some((f64::NEG_INFINITY, f64::INFINITY));
    }
    let discriminant = b * b - a * c;
    (discriminant >= 0.0).then(|| ((-b - discriminant.sqrt()) / a, (-b + discriminant.sqrt()) / a))
}
