//! Local frames `(t, b, N)`: direction cells are defined in them (`docs/design.md` §2).

use glam::DVec3;

/// A right-handed orthonormal frame with `normal` as its z axis.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Frame {
    /// First tangent, the local x axis.
    pub tangent: DVec3,
    /// Second tangent, the local y axis (`normal × tangent`).
    pub bitangent: DVec3,
    /// Unit normal, the local z axis.
    pub normal: DVec3,
}

impl Frame {
    /// Any frame around a unit normal.
    pub fn around(normal: DVec3) -> Frame {
        let (tangent, bitangent) = normal.any_orthonormal_pair();
        Frame { tangent, bitangent, normal }
    }

    /// A world direction in local coordinates.
    #[inline]
    pub fn local(&self, v: DVec3) -> DVec3 {
        DVec3::new(v.dot(self.tangent), v.dot(self.bitangent), v.dot(self.normal))
    }

    /// A local direction in world coordinates.
    #[inline]
    pub fn world(&self, v: DVec3) -> DVec3 {
        self.tangent * v.x + self.bitangent * v.y + self.normal * v.z
    }
}
