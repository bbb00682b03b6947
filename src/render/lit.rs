//! A solved scene ready for looking at: patches, a ray caster over their faces, and
//! the luminance each patch sends in each direction cell.

use crate::directions::DirectionSet;
use crate::geometry::{Mesh, NO_TWIN};
use crate::visibility::{NO_FACE, Visibility};
use glam::DVec3;

pub struct LitScene {
    pub mesh: Mesh,
    pub directions: DirectionSet,
    /// Luminance of patch `i` in cell `k` at `i·K + k`, cd/m².
    pub luminance: Vec<f64>,
    visibility: Visibility,
    /// The (up to two, back to back) patches of each face.
    faces: Vec<[u32; 2]>,
}

impl LitScene {
    /// `luminance` must hold `mesh.len() · directions.len()` values.
    pub fn new(mesh: Mesh, directions: DirectionSet, luminance: Vec<f64>) -> LitScene {
        let mut faces = vec![[NO_TWIN; 2]; mesh.faces];
        for (i, p) in mesh.patches.iter().enumerate() {
            let slot = &mut faces[p.face as usize];
            let free = if slot[0] == NO_TWIN { 0 } else { 1 };
            slot[free] = i as u32;
        }
        let visibility = Visibility::build(&mesh);
        LitScene { mesh, directions, luminance, visibility, faces }
    }

    /// Luminance seen from `origin` looking along the unit `direction`, cd/m²: that of
    /// the first face hit, from its patch facing the eye, in the cell pointing back
    /// at the eye. Zero for a miss and for the back of a one-sided surface (unless the
    /// direction set covers the sphere, whose lower cells hold transmitted light).
    pub fn luminance_along(&self, origin: DVec3, direction: DVec3) -> f64 {
        let Some(hit) = self.visibility.closest_hit(origin, direction, NO_FACE) else { return 0.0 };
        let [a, b] = self.faces[hit.face as usize];
        let facing = |i: u32| i != NO_TWIN && self.mesh.patches[i as usize].normal.dot(-direction) > 0.0;
        let patch = match (facing(a), facing(b)) {
            (true, _) => a,
            (_, true) => b,
            _ if self.directions.is_sphere() => a,
            _ => return 0.0,
        } as usize;
        let local = self.mesh.patches[patch].frame().local(-direction);
        let k = self.directions.lookup(local);
        self.luminance[patch * self.directions.len() + k]
    }
}
