//! A solved scene ready for looking at: patches, a ray caster over their faces, the
//! luminance each patch sends in each direction cell, and how a hit point is shaded.
//!
//! Three shadings of the luminance `L(q, −ray)` seen at a hit point `q`:
//! * `Flat`: the stored value `L(i, k)` of the patch hit, in the cell pointing at the eye;
//! * `Smooth`: that value interpolated between the corners of the patch, each corner
//!   holding the area-weighted mean over the patches of the same surface that share it
//!   (`smooth.rs`);
//! * `Gather`: one more reflection evaluated at `q` itself, `L(q,k) = Le + Σ_d ρ̄(k,d) I_d(q)`,
//!   from the solved field and the luminaires' direct light (`gather.rs`, `design.md` §5).

use super::gather::final_gather;
use super::random::Rng;
use super::smooth::Corners;
use crate::brdf::Block;
use crate::directions::DirectionSet;
use crate::geometry::{Mesh, NO_TWIN};
use crate::luminaire::Source;
use crate::visibility::{NO_FACE, Visibility};
use glam::DVec3;

/// How a hit point is shaded.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Shading {
    Flat,
    Smooth,
    /// A final gather with this many rays per pixel (spread over the pixel's samples).
    Gather {
        rays: usize,
    },
}

pub struct LitScene {
    pub mesh: Mesh,
    pub directions: DirectionSet,
    /// Luminance of patch `i` in cell `k` at `i·K + k`, cd/m².
    pub luminance: Vec<f64>,
    pub(super) visibility: Visibility,
    /// The (up to two, back to back) patches of each face.
    faces: Vec<[u32; 2]>,
    shading: Shading,
    corners: Option<Corners>,
    /// Material blocks (by material index) for the final gather.
    pub(super) blocks: Vec<Block>,
    /// Patches with a self-emission, for the gather's direct part.
    pub(super) emitters: Vec<u32>,
    /// The luminaires, whose direct light the gather adds exactly at its point.
    pub(super) sources: Vec<Source>,
}

impl LitScene {
    /// A flat-shaded scene. `luminance` holds `mesh.len() · directions.len()` values;
    /// `blocks[m]` is the material block (for the final gather) of every material index
    /// `m` the patches use.
    pub fn new(mesh: Mesh, directions: DirectionSet, luminance: Vec<f64>, blocks: Vec<Block>) -> LitScene {
        assert!(mesh.patches.iter().all(|p| (p.material as usize) < blocks.len()), "a block for every material");
        let mut faces = vec![[NO_TWIN; 2]; mesh.faces];
        for (i, p) in mesh.patches.iter().enumerate() {
            let slot = &mut faces[p.face as usize];
            let free = if slot[0] == NO_TWIN { 0 } else { 1 };
            slot[free] = i as u32;
        }
        let visibility = Visibility::build(&mesh);
        let emitters = (0..mesh.len() as u32).filter(|&i| mesh.emission[i as usize] > 0.0).collect();
        LitScene {
            mesh,
            directions,
            luminance,
            visibility,
            faces,
            shading: Shading::Flat,
            corners: None,
            blocks,
            emitters,
            sources: Vec::new(),
        }
    }

    /// The scene lit also by `sources` (their light is in the stored field; the final
    /// gather adds their direct light at its point).
    pub fn with_luminaires(mut self, sources: Vec<Source>) -> LitScene {
        self.sources = sources;
        self
    }

    /// Shades from now on with `shading`.
    pub fn set_shading(&mut self, shading: Shading) {
        if shading == Shading::Smooth && self.corners.is_none() {
            self.corners = Some(Corners::of(&self.mesh));
        }
        self.shading = shading;
    }

    pub fn shading(&self) -> Shading {
        self.shading
    }

    /// Luminance seen from `origin` looking along the unit `direction`, cd/m²: that of
    /// the first face hit, from its side facing the eye, shaded as chosen. `rays` is the
    /// gather's ray count for this sample, `rng` its random stream. Zero for a miss and
    /// for the back of a one-sided surface (unless the direction set covers the sphere,
    /// whose lower cells hold transmitted light).
    pub fn luminance_along(&self, origin: DVec3, direction: DVec3, rays: usize, rng: &mut Rng) -> f64 {
        let Some((patch, distance)) = self.hit(origin, direction) else { return 0.0 };
        let towards = -direction;
        match self.shading {
            Shading::Flat => self.flat(patch, towards),
            Shading::Smooth => {
                let corners = self.corners.as_ref().expect("set_shading builds the corners");
                corners.smooth(self, patch, origin + direction * distance, towards)
            }
            Shading::Gather { .. } => final_gather(self, patch, origin + direction * distance, towards, rays, rng),
        }
    }

    /// The patch first hit along the ray (the one facing back along it) and the distance.
    pub(super) fn hit(&self, origin: DVec3, direction: DVec3) -> Option<(usize, f64)> {
        self.hit_ignoring(origin, direction, NO_FACE)
    }

    pub(super) fn hit_ignoring(&self, origin: DVec3, direction: DVec3, ignore: u32) -> Option<(usize, f64)> {
        let hit = self.visibility.closest_hit(origin, direction, ignore)?;
        let [a, b] = self.faces[hit.face as usize];
        let facing = |i: u32| i != NO_TWIN && self.mesh.patches[i as usize].normal.dot(-direction) > 0.0;
        let patch = match (facing(a), facing(b)) {
            (true, _) => a,
            (_, true) => b,
            _ if self.directions.is_sphere() => a,
            _ => return None,
        };
        Some((patch as usize, hit.distance))
    }

    /// The stored luminance of `patch` in the cell holding the unit direction `towards`.
    pub(super) fn flat(&self, patch: usize, towards: DVec3) -> f64 {
        let k = self.directions.lookup(self.mesh.patches[patch].frame().local(towards));
        self.luminance[patch * self.directions.len() + k]
    }
}
