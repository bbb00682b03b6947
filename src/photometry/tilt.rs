//! Lamp output against the tilt of the luminaire (IES LM-63 `TILT=INCLUDE`): a table of
//! multiplying factors over tilt angles, for lamps whose output depends on their burning
//! position (metal halide).
//!
//! The tilt angle depends on how the lamp sits in the luminaire (the file's
//! lamp-to-luminaire geometry), measured in the scene (`y` up) from the luminaire's frame:
//! 1 — vertical lamp: the angle between the luminaire's up axis and the vertical;
//! 2 — horizontal lamp that stays horizontal when the luminaire is tilted in its C0–C180
//! plane, i.e. lying along the C90 axis: the elevation of that axis;
//! 3 — horizontal lamp along the C0 axis: the elevation of the C0 axis.
//! Factors are interpolated linearly and held constant beyond the first and last angle.

use glam::DVec3;

/// The `TILT=INCLUDE` record of an IES file.
#[derive(Debug, Clone, PartialEq)]
pub struct Tilt {
    /// Lamp-to-luminaire geometry, 1, 2 or 3.
    pub geometry: u8,
    /// Tilt angles, degrees, increasing.
    pub angles: Vec<f64>,
    /// Multiplying factor at each angle.
    pub factors: Vec<f64>,
}

impl Tilt {
    /// The factor at `angle` degrees.
    pub fn factor(&self, angle: f64) -> f64 {
        let (a, f) = (&self.angles, &self.factors);
        let last = a.len() - 1;
        if angle <= a[0] {
            return f[0];
        }
        if angle >= a[last] {
            return f[last];
        }
        let i = a.partition_point(|&v| v <= angle) - 1;
        let t = (angle - a[i]) / (a[i + 1] - a[i]);
        f[i] * (1.0 - t) + f[i + 1] * t
    }

    /// The tilt angle, degrees, of a luminaire whose frame axes (C0, C90, up) are given in
    /// scene coordinates.
    pub fn angle(&self, c0: DVec3, c90: DVec3, up: DVec3) -> f64 {
        let elevation = |axis: DVec3| axis.dot(DVec3::Y).abs().clamp(0.0, 1.0).asin().to_degrees();
        match self.geometry {
            1 => up.dot(DVec3::Y).clamp(-1.0, 1.0).acos().to_degrees(),
            2 => elevation(c90),
            _ => elevation(c0),
        }
    }
}
