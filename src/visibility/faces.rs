//! Patches by face: the (up to two, back to back) patches of each geometric face, and
//! which of them a ray meets or a point lies on. The one place that turns a hit face into
//! a patch, for renders, probes and the Monte Carlo estimators.

use super::{NO_FACE, Visibility};
use crate::geometry::{Mesh, NO_TWIN};
use glam::DVec3;

/// Where a ray lands: the face, its patch facing back along the ray (none on the back of
/// a one-sided surface) and the point hit, on the face's plane.
#[derive(Debug, Clone, Copy)]
pub struct Landing {
    /// The face hit.
    pub face: u32,
    /// Its patch facing back along the ray (none on the back of a one-sided surface).
    pub facing: Option<usize>,
    /// The point hit, on the face's plane, m.
    pub point: DVec3,
}

/// The patches of every face of a mesh.
#[derive(Debug, Clone)]
pub struct Faces {
    patches: Vec<[u32; 2]>,
}

impl Faces {
    /// The patches of every face of `mesh` (one, or two for a two-sided face).
    pub fn of(mesh: &Mesh) -> Faces {
        let mut patches = vec![[NO_TWIN; 2]; mesh.faces];
        for (i, p) in mesh.patches.iter().enumerate() {
            let slot = &mut patches[p.face as usize];
            slot[usize::from(slot[0] != NO_TWIN)] = i as u32;
        }
        Faces { patches }
    }

    /// The patch of `face` whose normal has a positive component along the unit `towards`.
    pub fn facing(&self, mesh: &Mesh, face: u32, towards: DVec3) -> Option<usize> {
        self.patches[face as usize]
            .into_iter()
            .find(|&i| i != NO_TWIN && mesh.patches[i as usize].normal.dot(towards) > 0.0)
            .map(|i| i as usize)
    }

    /// The first patch of `face` (the front one of a two-sided element).
    pub fn first(&self, face: u32) -> usize {
        self.patches[face as usize][0] as usize
    }

    /// The first face along the unit `direction` from `origin` (ignoring face `ignore`),
    /// the patch of it that faces back along the ray (if any), and the point hit.
    pub fn landing(
        &self,
        mesh: &Mesh,
        visibility: &Visibility,
        origin: DVec3,
        direction: DVec3,
        ignore: u32,
    ) -> Option<Landing> {
        let hit = visibility.closest_hit(origin, direction, ignore)?;
        // The hit distance is single precision: put the point back onto the face's plane.
        let plane = &mesh.patches[self.first(hit.face)];
        let point = origin + direction * hit.distance;
        let point = point - plane.normal * plane.normal.dot(point - plane.centroid);
        Some(Landing { face: hit.face, facing: self.facing(mesh, hit.face, -direction), point })
    }

    /// The patch a ray from `origin` along the unit `direction` lands on (ignoring face
    /// `ignore`) and the point: the patch facing back along the ray; the back of a
    /// one-sided face is a miss unless `sphere` (the direction cells cover the sphere,
    /// whose lower cells hold transmitted light), which gives the face's first patch.
    pub fn landing_patch(
        &self,
        mesh: &Mesh,
        visibility: &Visibility,
        origin: DVec3,
        direction: DVec3,
        ignore: u32,
        sphere: bool,
    ) -> Option<(usize, DVec3)> {
        let hit = self.landing(mesh, visibility, origin, direction, ignore)?;
        let patch = match hit.facing {
            Some(i) => i,
            None if sphere => self.first(hit.face),
            None => return None,
        };
        Some((patch, hit.point))
    }

    /// The patch that the point `p` lies on, facing the unit `n` (normal within 60°): a
    /// ray from `p + δn` towards `−n` hits its face within `2δ`, `δ` the [`standoff`].
    pub fn under(&self, mesh: &Mesh, visibility: &Visibility, p: DVec3, n: DVec3) -> Option<usize> {
        let delta = standoff(mesh);
        let hit = visibility.closest_hit(p + n * delta, -n, NO_FACE)?;
        if hit.distance > 2.0 * delta {
            return None;
        }
        self.facing(mesh, hit.face, n).filter(|&i| mesh.patches[i].normal.dot(n) > 0.5)
    }
}

/// How far above a surface a ray starts that must find it: `1e-4` of the scene's extent.
pub fn standoff(mesh: &Mesh) -> f64 {
    1e-4 * mesh.extent()
}
