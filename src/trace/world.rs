//! The scene as the Monte Carlo estimators see it: the patches only as geometry (where a
//! ray lands, which side it meets, or whether it leaves the scene), the continuous material
//! of every patch, the emitters, the luminaires, the openings (and their photons) and the ray caster. Nothing
//! here is discretized in direction: the references of `docs/design.md` §4 share no
//! kernel, block or cell with the linear system.

use super::daylight_photons::DaylightPhotons;
use super::emitters::Emitters;
use super::luminaires::Luminaires;
use super::openings::Openings;
use crate::geometry::Mesh;
use crate::luminaire::Source;
use crate::material::MaterialModel;
use crate::progress::Silent;
use crate::scene::Scene;
use crate::transfer::exposure::measure_exposure;
use crate::visibility::{Faces, NO_FACE, Visibility};
use glam::DVec3;

/// A ray's first surface, on the side it meets.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Landing {
    /// The patch facing the ray (its normal against the ray's direction).
    pub patch: usize,
    /// The point hit, m.
    pub point: DVec3,
}

/// What a ray meets.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Cast {
    /// A surface, on its receiving side.
    Lands(Landing),
    /// The back of a one-sided surface, which absorbs.
    Absorbed,
    /// Nothing: the ray leaves the scene.
    Escapes,
}

/// Geometry, materials and emitters of a scene, ready for tracing.
pub struct World {
    /// The patches, as geometry.
    pub mesh: Mesh,
    /// The ray caster over their faces.
    pub visibility: Visibility,
    /// The emitting patches, chosen by flux.
    pub emitters: Emitters,
    /// The luminaires, sampled exactly.
    pub luminaires: Luminaires,
    /// The openings through which the sky is seen.
    pub openings: Openings,
    /// The photons of the sky and the sun through the openings.
    pub daylight: DaylightPhotons,
    /// The material model of every patch.
    materials: Vec<MaterialModel>,
    faces: Faces,
}

impl World {
    /// `mesh` must be `scene`'s (its patches name the scene's materials); its patches'
    /// exposed areas are measured (`transfer::exposure`), which the forward tracer bins by.
    pub fn new(scene: &Scene, mut mesh: Mesh) -> World {
        let visibility = Visibility::build_for(&scene.surfaces, &mesh);
        measure_exposure(&mut mesh, &visibility, &Silent);
        World::with_visibility(scene, mesh, visibility)
    }

    /// [`World::new`] with a ray caster already built over `mesh` (exposure measured).
    pub fn with_visibility(scene: &Scene, mesh: Mesh, visibility: Visibility) -> World {
        let faces = Faces::of(&mesh);
        let materials = mesh.patches.iter().map(|p| scene.materials[p.material as usize].model.clone()).collect();
        let emitters = Emitters::of(&mesh);
        let sources: Vec<Source> = scene.luminaires.iter().map(Source::of).collect();
        let openings = Openings::of(&sources);
        let daylight = DaylightPhotons::of(&sources, &visibility);
        let luminaires = match openings.is_empty() {
            true => Luminaires::of(scene, &mesh),
            false => Luminaires::of(scene, &mesh).without_beams(),
        };
        World { mesh, visibility, emitters, luminaires, openings, daylight, materials, faces }
    }

    /// The flux the photons of light tracing carry: the emitting surfaces', the luminaires'
    /// and the daylight's through the openings, lm.
    pub fn photon_flux(&self) -> f64 {
        self.emitters.flux() + self.luminaires.flux() + self.daylight.flux()
    }

    /// The material of patch `i`.
    #[inline]
    pub fn material(&self, i: usize) -> &MaterialModel {
        &self.materials[i]
    }

    /// The patch that the point `p` lies on, facing the unit `n`, if any.
    pub fn under(&self, p: DVec3, n: DVec3) -> Option<usize> {
        self.faces.under(&self.mesh, &self.visibility, p, n)
    }

    /// Whether the eye at `origin` looking along the unit `direction` meets a light
    /// source's own luminance first: a luminaire's luminous opening, or the sky through an
    /// opening.
    pub fn sees_light(&self, origin: DVec3, direction: DVec3) -> bool {
        let escapes = || matches!(self.cast(origin, direction, NO_FACE), Cast::Escapes);
        self.luminaires.seen(&self.visibility, origin, direction).is_some()
            || (escapes() && self.openings.seen(origin, direction).is_some())
    }

    /// The first surface along the unit `direction` from `origin`, ignoring face `ignore`;
    /// `None` for a miss and for the back of a one-sided surface (which absorbs).
    pub fn landing(&self, origin: DVec3, direction: DVec3, ignore: u32) -> Option<Landing> {
        match self.cast(origin, direction, ignore) {
            Cast::Lands(landing) => Some(landing),
            Cast::Absorbed | Cast::Escapes => None,
        }
    }

    /// What the ray along the unit `direction` from `origin` meets first, ignoring face
    /// `ignore`.
    pub fn cast(&self, origin: DVec3, direction: DVec3, ignore: u32) -> Cast {
        let Some(hit) = self.faces.landing(&self.mesh, &self.visibility, origin, direction, ignore) else {
            return Cast::Escapes;
        };
        match hit.facing {
            Some(patch) => Cast::Lands(Landing { patch, point: hit.point }),
            None => Cast::Absorbed,
        }
    }
}
