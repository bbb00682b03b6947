//! The patch mesh: every surface of a scene cut into planar patches (`docs/design.md` §2).
//!
//! Owns the per-patch record (centroid, normal, area, local frame, owning surface and
//! material, emitted luminance) and the rule for `inside` (normals flipped) and
//! `two_sided` (a second patch, back to back, on the same geometric face).

use super::frame::Frame;
use super::polygon::ConvexPolygon;
use super::surface::{Emission, Surface};
use super::tessellate::{element_count, tessellate};
use glam::DVec3;
use std::f64::consts::PI;

/// One planar patch `P_i`.
#[derive(Debug, Clone, Copy)]
pub struct Patch {
    /// The patch's polygon, m.
    pub polygon: ConvexPolygon,
    /// Centroid, m.
    pub centroid: DVec3,
    /// Unit normal of the reflecting side.
    pub normal: DVec3,
    /// Area, m².
    pub area: f64,
    /// The part of `area` outside every solid, m²: what the patch's luminance is spread
    /// over (`docs/design.md` §3, "Contacts"). The area itself until the model measures it
    /// (`transfer::exposure`): a patch under a cabinet standing on it, or behind a shelf
    /// against it, sends and receives light only through its exposed part.
    pub exposed: f64,
    /// Local frame `(tangent, bitangent, normal)`, right-handed.
    pub tangent: DVec3,
    /// Second tangent, `normal × tangent`.
    pub bitangent: DVec3,
    /// Index of the owning [`Surface`].
    pub surface: u32,
    /// Index of the patch's [`crate::scene::Material`].
    pub material: u32,
    /// Geometric face: the two patches of a two-sided element share it.
    pub face: u32,
    /// The patch on the other side of a two-sided element, or [`NO_TWIN`].
    pub twin: u32,
}

/// Marks a patch without a back-to-back twin.
pub const NO_TWIN: u32 = u32::MAX;

impl Patch {
    /// The local frame `(t, b, N)`.
    #[inline]
    pub fn frame(&self) -> Frame {
        Frame { tangent: self.tangent, bitangent: self.bitangent, normal: self.normal }
    }

    /// `flux` (lm) spread over the exposed area, lm/m² (0 when none of it is exposed).
    pub fn per_exposed_area(&self, flux: f64) -> f64 {
        if self.exposed > 0.0 { flux / self.exposed } else { 0.0 }
    }

    /// The patch of `polygon` with its derived quantities.
    pub fn from_polygon(polygon: ConvexPolygon, surface: u32, material: u32, face: u32) -> Patch {
        let normal = polygon.normal();
        let v = polygon.vertices();
        let tangent = (v[1] - v[0]).normalize();
        Patch {
            polygon,
            centroid: polygon.centroid(),
            normal,
            area: polygon.area(),
            exposed: polygon.area(),
            tangent,
            bitangent: normal.cross(tangent),
            surface,
            material,
            face,
            twin: NO_TWIN,
        }
    }
}

/// All patches of a scene with their emitted luminance.
#[derive(Debug, Clone)]
pub struct Mesh {
    /// Every patch, in mesh order (the unknowns' order).
    pub patches: Vec<Patch>,
    /// Emitted (Lambertian) luminance of each patch, cd/m².
    pub emission: Vec<f64>,
    /// Number of geometric faces (patches of a two-sided element share one).
    pub faces: usize,
}

impl Mesh {
    /// Meshes every surface with target edge length `patch_size` (m).
    pub fn build(surfaces: &[Surface], patch_size: f64) -> Mesh {
        // Reserved once from the count: grown by doubling, the patches would pass through
        // three times their bytes, past the memory forecast (issue 37, point 7).
        let count = Mesh::count(surfaces, patch_size);
        let mut patches = Vec::with_capacity(count as usize);
        let mut emission = Vec::with_capacity(count as usize);
        let mut faces = 0u32;
        for (s, surface) in surfaces.iter().enumerate() {
            let first = patches.len();
            for mut element in tessellate(&surface.shape, patch_size) {
                if surface.inside {
                    element = element.reversed();
                }
                let front = patches.len() as u32;
                patches.push(Patch::from_polygon(element, s as u32, surface.material as u32, faces));
                if surface.two_sided {
                    let mut back = Patch::from_polygon(element.reversed(), s as u32, surface.material as u32, faces);
                    back.twin = front;
                    patches[front as usize].twin = front + 1;
                    patches.push(back);
                }
                faces += 1;
            }
            let area: f64 = patches[first..].iter().map(|p| p.area).sum();
            let luminance = match surface.emission {
                None => 0.0,
                Some(Emission::Luminance(l)) => l,
                Some(Emission::Flux(phi)) => phi / (PI * area),
            };
            emission.resize(patches.len(), luminance);
        }
        Mesh { patches, emission, faces: faces as usize }
    }

    /// The patches [`Mesh::build`] makes of `surfaces` at `patch_size`, counted without making
    /// them (`element_count`; a two-sided surface twice), in floating point.
    pub fn count(surfaces: &[Surface], patch_size: f64) -> f64 {
        let sides = |s: &Surface| if s.two_sided { 2.0 } else { 1.0 };
        surfaces.iter().map(|s| sides(s) * element_count(&s.shape, patch_size)).sum()
    }

    /// The patches with a self-emission.
    pub fn emitters(&self) -> Vec<u32> {
        (0..self.len() as u32).filter(|&i| self.emission[i as usize] > 0.0).collect()
    }

    /// Number of patches.
    pub fn len(&self) -> usize {
        self.patches.len()
    }

    /// True when there are no patches.
    pub fn is_empty(&self) -> bool {
        self.patches.is_empty()
    }

    /// Length of the diagonal of the bounding box, m: the scene's length scale.
    pub fn extent(&self) -> f64 {
        let (mut lo, mut hi) = (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY));
        for p in &self.patches {
            for v in p.polygon.vertices() {
                lo = lo.min(*v);
                hi = hi.max(*v);
            }
        }
        (hi - lo).length()
    }

    /// Total meshed area of each surface (both sides of a two-sided one), m².
    pub fn surface_areas(&self, surfaces: usize) -> Vec<f64> {
        let mut areas = vec![0.0; surfaces];
        for p in &self.patches {
            areas[p.surface as usize] += p.area;
        }
        areas
    }
}
