//! Plane mirrors as windows into a mirrored copy of the scene (the image method; Wallace,
//! Cohen & Greenberg 1987): the light that patch `j` sends to patch `i` by way of a plane
//! mirror `M` of reflectance `ρ_M` is what `j`'s mirror image `j′` (reflected across `M`'s
//! plane) sends to `i` through `M`'s polygon, times `ρ_M` (`docs/design.md` (3.10),
//! `docs/mirrors.md`).
//!
//! Owns which mirrors are plane mirrors ([`plane_mirrors`]), the reflection of points,
//! directions and patches across a mirror's plane, whether a segment to an image point
//! passes through the mirror with both of its legs unblocked ([`PlaneMirror::passes`]), and
//! the visibility fraction of an image pair from the kernel's stratified points
//! ([`image_fraction`], as [`super::occlusion::visible_fraction`] for a direct pair). It
//! knows nothing of materials: the caller says which materials mirror and how much.

use super::occlusion::{POINTS, VisibleFraction};
use crate::geometry::{Mesh, NO_TWIN, Patch, facing};
use crate::visibility::Visibility;
use glam::DVec3;

/// A plane mirror: the front patches of one mirror surface (or its back patches), all in
/// one plane, none emitting, and no other mirror patch facing them.
#[derive(Debug, Clone, PartialEq)]
pub struct PlaneMirror {
    /// A point of the plane, m.
    pub origin: DVec3,
    /// The unit normal of the reflecting side.
    pub normal: DVec3,
    /// Specular reflectance `ρ_M`.
    pub reflectance: f64,
    /// Its patches, ascending.
    pub patches: Vec<u32>,
    /// Their faces, ascending.
    faces: Vec<u32>,
}

impl PlaneMirror {
    /// The mirror image of the point `p`.
    pub fn reflect(&self, p: DVec3) -> DVec3 {
        p - 2.0 * (p - self.origin).dot(self.normal) * self.normal
    }

    /// The mirror image of the direction `w`.
    pub fn reflect_direction(&self, w: DVec3) -> DVec3 {
        w - 2.0 * w.dot(self.normal) * self.normal
    }

    /// Signed distance of `p` from the plane, positive in front, m.
    pub fn height(&self, p: DVec3) -> f64 {
        (p - self.origin).dot(self.normal)
    }

    /// True when some of `patch` lies in front of the plane.
    pub fn in_front(&self, patch: &Patch) -> bool {
        let eps = 1e-9 * patch.area.sqrt();
        patch.polygon.vertices().iter().any(|&v| self.height(v) > eps)
    }

    /// True when `patch` is one of the mirror's.
    pub fn holds(&self, patch: u32) -> bool {
        self.patches.binary_search(&patch).is_ok()
    }

    /// The image `j′` of `patch`: its polygon reflected (vertex order reversed, so that it
    /// faces the reflected normal) and its frame reflected, so that a direction `w` has in
    /// `j′`'s frame the local coordinates `R w` has in `patch`'s. The image's frame is
    /// left-handed; the direction cells only read local coordinates.
    pub fn image(&self, patch: &Patch) -> Patch {
        let mut v: Vec<DVec3> = patch.polygon.vertices().iter().map(|&x| self.reflect(x)).collect();
        v.reverse();
        Patch {
            polygon: crate::geometry::ConvexPolygon::from_slice(&v),
            centroid: self.reflect(patch.centroid),
            normal: self.reflect_direction(patch.normal),
            tangent: self.reflect_direction(patch.tangent),
            bitangent: self.reflect_direction(patch.bitangent),
            ..*patch
        }
    }

    /// True when the light from `from` (in front of the plane, on face `from_face`) to the
    /// image point `to_image` crosses the plane inside the mirror, with nothing between
    /// `from` and the mirror and nothing between the mirror and the real point
    /// `reflect(to_image)` (on face `to_face`).
    pub fn passes(&self, visibility: &Visibility, from: DVec3, from_face: u32, to_image: DVec3, to_face: u32) -> bool {
        let (a, b) = (self.height(from), self.height(to_image));
        if a <= 0.0 || b >= 0.0 {
            return false;
        }
        let x = from + (to_image - from) * (a / (a - b));
        let Some(hit) = visibility.closest_hit(from, x - from, from_face) else { return false };
        self.faces.binary_search(&hit.face).is_ok()
            && visibility.visible(x, self.reflect(to_image), [hit.face, to_face])
    }
}

/// The plane mirrors of `mesh`, `reflectance[m]` being the specular reflectance of material
/// `m` when it is a mirror. The patches of one mirror surface on one side form a plane
/// mirror when they are coplanar, none emits, and no other mirror patch faces them (light
/// between two mirrors would need an image of an image; such mirrors keep the kernel's
/// cell-to-cell reflection).
pub fn plane_mirrors(mesh: &Mesh, reflectance: &[Option<f64>]) -> Vec<PlaneMirror> {
    let mirroring = |i: usize| reflectance.get(mesh.patches[i].material as usize).copied().flatten();
    let mut groups: Vec<((u32, bool), Vec<u32>)> = Vec::new();
    for (i, p) in mesh.patches.iter().enumerate() {
        if mirroring(i).is_none() {
            continue;
        }
        let key = (p.surface, p.twin != NO_TWIN && (p.twin as usize) < i);
        match groups.iter_mut().find(|(k, _)| *k == key) {
            Some((_, members)) => members.push(i as u32),
            None => groups.push((key, vec![i as u32])),
        }
    }
    let all: Vec<u32> = groups.iter().flat_map(|(_, m)| m.iter().copied()).collect();
    groups
        .iter()
        .filter_map(|(_, members)| {
            let first = &mesh.patches[members[0] as usize];
            let extent = mesh.extent();
            let planar = members.iter().all(|&i| {
                let p = &mesh.patches[i as usize];
                p.normal.dot(first.normal) > 1.0 - 1e-12
                    && p.polygon
                        .vertices()
                        .iter()
                        .all(|&v| (v - first.centroid).dot(first.normal).abs() <= 1e-9 * extent)
            });
            let dark = members.iter().all(|&i| mesh.emission[i as usize] == 0.0);
            let alone = all
                .iter()
                .filter(|i| !members.contains(i))
                .all(|&o| members.iter().all(|&i| !facing(&mesh.patches[i as usize], &mesh.patches[o as usize])));
            (planar && dark && alone).then(|| {
                let mut faces: Vec<u32> = members.iter().map(|&i| mesh.patches[i as usize].face).collect();
                faces.sort_unstable();
                PlaneMirror {
                    origin: first.centroid,
                    normal: first.normal,
                    reflectance: mirroring(members[0] as usize).unwrap_or(0.0),
                    patches: members.clone(),
                    faces,
                }
            })
        })
        .collect()
}

/// Fraction of the `POINTS²` segments between the points `pa` of `a` and the images of the
/// points `pb` of `b` that pass through `mirror` (see [`PlaneMirror::passes`]). As for a
/// direct pair, the four segments from point `k` to point `k` are tried first, and all of
/// them only where those disagree.
pub fn image_fraction(
    visibility: &Visibility,
    mirror: &PlaneMirror,
    a: &Patch,
    pa: &[DVec3; POINTS],
    b: &Patch,
    pb: &[DVec3; POINTS],
) -> VisibleFraction {
    let passes = |k: usize, m: usize| mirror.passes(visibility, pa[k], a.face, mirror.reflect(pb[m]), b.face);
    let first = (0..POINTS).filter(|&k| passes(k, k)).count();
    if first == 0 || first == POINTS {
        return VisibleFraction { fraction: (first / POINTS) as f64, rays: 2 * POINTS };
    }
    let mut seen = 0;
    for k in 0..POINTS {
        for m in 0..POINTS {
            seen += passes(k, m) as usize;
        }
    }
    VisibleFraction { fraction: seen as f64 / (POINTS * POINTS) as f64, rays: 2 * (POINTS + POINTS * POINTS) }
}
