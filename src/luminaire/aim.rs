//! The frame of an aimed luminaire: C0 axis, C90 axis and up (`−aim`), in scene coordinates.
//!
//! The C0 axis is the scene's `x` axis made perpendicular to the aim (the `z` axis when the
//! aim is within 8° of `±x`), then turned by `rotate_deg` about the up axis,
//! counter-clockwise seen from behind the luminaire (from C0 towards C90). C90 = up × C0,
//! so `(C0, C90, up)` is right-handed and `Frame::local` gives luminaire coordinates.

use crate::geometry::Frame;
use glam::DVec3;

/// The luminaire frame of a unit `aim` turned by `rotate_deg` degrees.
pub fn frame(aim: DVec3, rotate_deg: f64) -> Frame {
    let up = -aim;
    let reference = if aim.x.abs() > 0.99 { DVec3::Z } else { DVec3::X };
    let c0 = (reference - up * reference.dot(up)).normalize();
    let c90 = up.cross(c0);
    let (s, c) = rotate_deg.to_radians().sin_cos();
    let turned = c0 * c + c90 * s;
    Frame { tangent: turned, bitangent: up.cross(turned), normal: up }
}
