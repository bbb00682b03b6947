//! A solved scene ready for looking at (`solved.rs`) and how a hit point is shaded.
//!
//! Three shadings of the luminance `L(q, −ray)` seen at a hit point `q`:
//! * `Flat`: the stored value `L(i, k)` of the patch hit, in the cell pointing at the eye;
//! * `Smooth`: that value interpolated between the corners of the patch, each corner
//!   holding the area-weighted mean over the patches of the same surface that share it
//!   (`smooth.rs`);
//! * `Gather`: one more reflection evaluated at `q` itself with the material's own
//!   luminance factor, from the solved field and the luminaires' direct light
//!   (`crate::readout::final_gather`, `docs/design.md` §5).

use super::smooth::Corners;
use super::solved::Solved;
use crate::directions::DirectionSet;
use crate::geometry::{Mesh, NO_TWIN};
use crate::luminaire::Source;
use crate::material::MaterialModel;
use crate::random::Rng;
use crate::readout::final_gather::final_gather;
use glam::DVec3;

/// How a hit point is shaded.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Shading {
    /// The stored luminance of the patch hit, in the cell towards the eye.
    Flat,
    /// Interpolated over the corners that patches of the same surface share.
    Smooth,
    /// A final gather with this many rays per pixel, spread over the pixel's shaded points
    /// (at most [`super::GATHER_POINTS`]).
    Gather {
        /// Final-gather rays per pixel.
        rays: usize,
    },
}

/// A solved scene ready to render: what the rays see and how a hit is shaded.
pub struct LitScene {
    /// What the rays see.
    pub solved: Solved,
    shading: Shading,
    corners: Option<Corners>,
}

impl LitScene {
    /// A flat-shaded scene. `luminance` holds `mesh.len() · directions.len()` values;
    /// `materials[m]` is the material (for the final gather) of every material index `m`
    /// the patches use.
    pub fn new(mesh: Mesh, directions: DirectionSet, luminance: Vec<f64>, materials: Vec<MaterialModel>) -> LitScene {
        assert!(mesh.patches.iter().all(|p| (p.material as usize) < materials.len()), "a material for each index");
        LitScene { solved: Solved::new(mesh, directions, luminance, materials), shading: Shading::Flat, corners: None }
    }

    /// The scene lit also by `sources` (their light is in the stored field; the final
    /// gather adds their direct light at its point).
    pub fn with_luminaires(mut self, sources: Vec<Source>) -> LitScene {
        self.solved.sources = sources;
        self
    }

    /// Shades from now on with `shading`.
    pub fn set_shading(&mut self, shading: Shading) {
        if shading == Shading::Smooth && self.corners.is_none() {
            self.corners = Some(Corners::of(&self.solved.mesh));
        }
        self.shading = shading;
    }

    /// The current shading.
    pub fn shading(&self) -> Shading {
        self.shading
    }

    /// Luminance seen from `origin` looking along the unit `direction`, cd/m²: that of
    /// the first face hit, from its side facing the eye, shaded as chosen. `rays` is the
    /// gather's ray count for this sample, `rng` its random stream. Zero for a miss and
    /// for the back of a one-sided surface (unless the direction set covers the sphere,
    /// whose lower cells hold transmitted light).
    pub fn luminance_along(&self, origin: DVec3, direction: DVec3, rays: usize, rng: &mut Rng) -> f64 {
        match self.solved.hit(origin, direction) {
            Some((patch, point)) => self.shade(patch, point, -direction, rays, rng),
            None => 0.0,
        }
    }

    /// The patch first hit along a ray and the point hit (see [`LitScene::luminance_along`]).
    pub(super) fn hit(&self, origin: DVec3, direction: DVec3) -> Option<(usize, DVec3)> {
        self.solved.hit(origin, direction)
    }

    /// Which surface and side `patch` belongs to, as one key.
    pub(super) fn side_of(&self, patch: usize) -> u64 {
        let p = &self.solved.mesh.patches[patch];
        let back = p.twin != NO_TWIN && (p.twin as usize) < patch;
        (p.surface as u64) << 1 | back as u64
    }

    /// The luminance `patch` sends from its point `point` towards the unit `towards`.
    pub(super) fn shade(&self, patch: usize, point: DVec3, towards: DVec3, rays: usize, rng: &mut Rng) -> f64 {
        let solved = &self.solved;
        match self.shading {
            Shading::Flat => solved.flat(patch, towards),
            Shading::Smooth => {
                let corners = self.corners.as_ref().expect("set_shading builds the corners");
                corners.smooth(solved, patch, point, towards)
            }
            Shading::Gather { .. } => final_gather(solved, patch, point, towards, rays, rng),
        }
    }
}
