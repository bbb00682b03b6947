//! The scene as the Monte Carlo estimators see it: the patches only as geometry (where a
//! ray lands, which side it meets), the continuous material of every patch, the emitters,
//! the luminaires and the ray caster. Nothing here is discretized in direction: `design.md` §4's
//! references share no kernel, block or cell with the linear system.

use super::emitters::Emitters;
use super::luminaires::Luminaires;
use crate::geometry::{Mesh, NO_TWIN};
use crate::scene::{MaterialModel, Scene};
use crate::visibility::Visibility;
use glam::DVec3;

/// A ray's first surface, on the side it meets.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Landing {
    /// The patch facing the ray (its normal against the ray's direction).
    pub patch: usize,
    pub point: DVec3,
}

/// Geometry, materials and emitters of a scene, ready for tracing.
pub struct World {
    pub mesh: Mesh,
    pub visibility: Visibility,
    pub emitters: Emitters,
    pub luminaires: Luminaires,
    /// The material model of every patch.
    materials: Vec<MaterialModel>,
    /// The (up to two, back to back) patches of each face.
    faces: Vec<[u32; 2]>,
}

impl World {
    /// `mesh` must be `scene`'s (its patches name the scene's materials).
    pub fn new(scene: &Scene, mesh: Mesh) -> World {
        let visibility = Visibility::build(&mesh);
        World::with_visibility(scene, mesh, visibility)
    }

    /// [`World::new`] with a ray caster already built over `mesh`.
    pub fn with_visibility(scene: &Scene, mesh: Mesh, visibility: Visibility) -> World {
        let mut faces = vec![[NO_TWIN; 2]; mesh.faces];
        for (i, p) in mesh.patches.iter().enumerate() {
            let slot = &mut faces[p.face as usize];
            slot[usize::from(slot[0] != NO_TWIN)] = i as u32;
        }
        let materials = mesh.patches.iter().map(|p| scene.materials[p.material as usize].model.clone()).collect();
        let emitters = Emitters::of(&mesh);
        let luminaires = Luminaires::of(scene, &mesh);
        World { mesh, visibility, emitters, luminaires, materials, faces }
    }

    /// The material of patch `i`.
    #[inline]
    pub fn material(&self, i: usize) -> &MaterialModel {
        &self.materials[i]
    }

    /// The first surface along the unit `direction` from `origin`, ignoring face `ignore`;
    /// `None` for a miss and for the back of a one-sided surface (which absorbs).
    pub fn landing(&self, origin: DVec3, direction: DVec3, ignore: u32) -> Option<Landing> {
        let hit = self.visibility.closest_hit(origin, direction, ignore)?;
        let facing = |i: u32| i != NO_TWIN && self.mesh.patches[i as usize].normal.dot(direction) < 0.0;
        let [a, b] = self.faces[hit.face as usize];
        let patch = if facing(a) {
            a
        } else if facing(b) {
            b
        } else {
            return None;
        };
        // The hit distance is single precision: put the point back onto the patch's plane.
        let p = &self.mesh.patches[patch as usize];
        let point = origin + direction * hit.distance;
        let point = point - p.normal * p.normal.dot(point - p.centroid);
        Some(Landing { patch: patch as usize, point })
    }
}
