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
//!
//! What the eye meets first along a ray is a [`Sight`]: a patch to shade, or a light
//! source's own luminance: a luminaire's luminous opening nearer than the patch
//! (`crate::luminaire::luminous_along`), or, where the ray leaves the scene through a `[[window]]`, the sky
//! above the horizon and the ground below it times the glazing's `τ(θ)`
//! (`crate::trace::openings`, the boundary condition of `docs/design.md` §1).

use super::smooth::Corners;
use super::solved::Solved;
use crate::directions::DirectionSet;
use crate::geometry::{Mesh, NO_TWIN};
use crate::luminaire::{Source, luminous_along};
use crate::material::MaterialModel;
use crate::random::Rng;
use crate::readout::final_gather::final_gather;
use crate::trace::openings::Openings;
use crate::visibility::NO_FACE;
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

/// What the eye meets first along a ray.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Sight {
    /// A patch and the point hit on it.
    Patch(usize, DVec3),
    /// A light source's own luminance: a luminaire's luminous opening, or the sky or the
    /// ground through an opening, cd/m².
    Light(f64),
}

/// A solved scene ready to render: what the rays see and how a hit is shaded.
pub struct LitScene {
    /// What the rays see.
    pub solved: Solved,
    shading: Shading,
    corners: Option<Corners>,
    /// The `[[window]]` openings and the sky each shows.
    openings: Openings,
}

impl LitScene {
    /// A flat-shaded scene. `luminance` holds `mesh.len() · directions.len()` values;
    /// `materials[m]` is the material (for the final gather) of every material index `m`
    /// the patches use.
    pub fn new(mesh: Mesh, directions: DirectionSet, luminance: Vec<f64>, materials: Vec<MaterialModel>) -> LitScene {
        assert!(mesh.patches.iter().all(|p| (p.material as usize) < materials.len()), "a material for each index");
        let solved = Solved::new(mesh, directions, luminance, materials);
        LitScene { solved, shading: Shading::Flat, corners: None, openings: Openings::of(&[]) }
    }

    /// The scene lit also by `sources` (their light is in the stored field; the final
    /// gather adds their direct light at its point; the eye sees the luminaires' luminous
    /// openings and the sky through the openings).
    pub fn with_luminaires(mut self, sources: Vec<Source>) -> LitScene {
        self.openings = Openings::of(&sources);
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
    /// the first face hit, from its side facing the eye, shaded as chosen, or of the light
    /// source seen ([`Sight`]). `rays` is the gather's ray count for this sample, `rng` its
    /// random stream. Zero for a ray that leaves the scene elsewhere than through an
    /// opening, and for the back of a one-sided surface (unless the direction set covers
    /// the sphere, whose lower cells hold transmitted light).
    pub fn luminance_along(&self, origin: DVec3, direction: DVec3, rays: usize, rng: &mut Rng) -> f64 {
        match self.sight(origin, direction) {
            Some(Sight::Patch(patch, point)) => self.shade(patch, point, -direction, rays, rng),
            Some(Sight::Light(luminance)) => luminance,
            None => 0.0,
        }
    }

    /// What the eye at `origin` meets first along the unit `direction`, if anything.
    pub fn sight(&self, origin: DVec3, direction: DVec3) -> Option<Sight> {
        let hit = self.solved.hit(origin, direction);
        let before = hit.map_or(f64::INFINITY, |(_, q)| (q - origin).length());
        if let Some(luminance) = luminous_along(&self.solved.sources, origin, direction, before) {
            return Some(Sight::Light(luminance));
        }
        match hit {
            Some((patch, point)) => Some(Sight::Patch(patch, point)),
            None => self.outside(origin, direction).map(Sight::Light),
        }
    }

    /// The sky or the ground seen through an opening along a ray that leaves the scene.
    fn outside(&self, origin: DVec3, direction: DVec3) -> Option<f64> {
        let seen = self.openings.seen(origin, direction)?;
        Openings::clear(&self.solved.visibility, origin, direction, NO_FACE).then_some(seen.luminance)
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
