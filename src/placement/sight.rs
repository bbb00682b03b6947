//! What a ray from a point meets first: the distance, the patch facing back along the ray
//! (none on the back of a one-sided surface), and that patch's normal; and whether a point
//! lies on a surface of a given plane. Thin wrappers of `visibility::Faces` for the
//! placement's short casts.

use crate::trace::World;
use crate::visibility::Faces;
use glam::DVec3;

/// The first surface along a ray.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Seen {
    /// Distance from the ray's origin, m.
    pub distance: f64,
    /// The patch facing back along the ray; `None` on the back of a one-sided surface.
    pub patch: Option<usize>,
}

/// The scene's patches by face, for casts.
pub struct Sight<'a> {
    /// The scene as the tracers see it.
    pub world: &'a World,
    faces: Faces,
}

impl<'a> Sight<'a> {
    /// Casts over `world`.
    pub fn new(world: &'a World) -> Sight<'a> {
        Sight { world, faces: Faces::of(&world.mesh) }
    }

    /// The first surface along the unit `direction` from `origin`, ignoring face `ignore`.
    pub fn first(&self, origin: DVec3, direction: DVec3, ignore: u32) -> Option<Seen> {
        let w = self.world;
        let landing = self.faces.landing(&w.mesh, &w.visibility, origin, direction, ignore)?;
        Some(Seen { distance: (landing.point - origin).length(), patch: landing.facing })
    }

    /// The normal of a patch.
    pub fn normal(&self, patch: usize) -> DVec3 {
        self.world.mesh.patches[patch].normal
    }

    /// The patch under `x` facing the unit `n` in a plane parallel to it (the point lies on
    /// a surface of that plane), if any.
    pub fn on_plane(&self, x: DVec3, n: DVec3) -> Option<usize> {
        self.world.under(x, n).filter(|&i| self.normal(i).dot(n) > 0.999)
    }
}
