//! A solved scene as rays see it: the patches, a ray caster over their faces, the
//! luminance each patch sends in each direction cell, the materials, the emitters
//! and the luminaires. Which patch a ray meets, and its stored (flat) value there.

use crate::directions::DirectionSet;
use crate::geometry::Mesh;
use crate::luminaire::Source;
use crate::material::MaterialModel;
use crate::readout::final_gather::Surroundings;
use crate::visibility::{Faces, NO_FACE, Visibility};
use glam::DVec3;

/// A solved field as rays see it: the mesh, its ray caster, the luminance of every patch
/// and cell, the materials and the luminaires.
pub struct Solved {
    /// The patches the field lives on.
    pub mesh: Mesh,
    /// The direction cells of every patch.
    pub directions: DirectionSet,
    /// Luminance of patch `i` in cell `k` at `i·K + k`, cd/m².
    pub luminance: Vec<f64>,
    pub(super) visibility: Visibility,
    faces: Faces,
    /// The materials (by material index), whose luminance factors the final gather applies.
    pub(super) materials: Vec<MaterialModel>,
    /// Patches with a self-emission, for the gather's direct part.
    pub(super) emitters: Vec<u32>,
    /// The luminaires, whose direct light the gather adds exactly at its point.
    pub(super) sources: Vec<Source>,
}

impl Solved {
    /// `luminance` holds `mesh.len() · directions.len()` values; `materials[m]` is the
    /// material of every material index `m` the patches use (checked by the caller).
    pub(super) fn new(
        mesh: Mesh,
        directions: DirectionSet,
        luminance: Vec<f64>,
        materials: Vec<MaterialModel>,
    ) -> Solved {
        let faces = Faces::of(&mesh);
        let visibility = Visibility::build(&mesh);
        let emitters = mesh.emitters();
        Solved { mesh, directions, luminance, visibility, faces, materials, emitters, sources: Vec::new() }
    }

    /// The patch first hit along the ray (the one facing back along it) and the point hit.
    pub(super) fn hit(&self, origin: DVec3, direction: DVec3) -> Option<(usize, DVec3)> {
        self.hit_ignoring(origin, direction, NO_FACE)
    }

    /// [`Solved::hit`] ignoring face `ignore`. The back of a one-sided surface is a miss,
    /// unless the direction set covers the sphere (its lower cells hold transmitted light).
    pub(super) fn hit_ignoring(&self, origin: DVec3, direction: DVec3, ignore: u32) -> Option<(usize, DVec3)> {
        let sphere = self.directions.is_sphere();
        self.faces.landing_patch(&self.mesh, &self.visibility, origin, direction, ignore, sphere)
    }

    /// The stored luminance of `patch` in the cell holding the unit direction `towards`.
    pub(super) fn flat(&self, patch: usize, towards: DVec3) -> f64 {
        let k = self.directions.lookup(self.mesh.patches[patch].frame().local(towards));
        self.luminance[patch * self.directions.len() + k]
    }
}

impl Surroundings for Solved {
    fn mesh(&self) -> &Mesh {
        &self.mesh
    }

    fn visibility(&self) -> &Visibility {
        &self.visibility
    }

    fn material(&self, patch: usize) -> &MaterialModel {
        &self.materials[self.mesh.patches[patch].material as usize]
    }

    fn emitters(&self) -> &[u32] {
        &self.emitters
    }

    fn sources(&self) -> &[Source] {
        &self.sources
    }

    fn met(&self, q: DVec3, w: DVec3, face: u32) -> Option<(usize, f64)> {
        self.hit_ignoring(q, w, face).map(|(j, _)| (j, self.flat(j, -w)))
    }
}
