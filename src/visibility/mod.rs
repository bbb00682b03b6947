//! Visibility: the pupil function `Θ(r, r')` of `docs/design.md` §1 and closest hits, through `obvhs`.
//!
//! Owns the only conversion of the scene to `f32` (obvhs works in `Vec3A`), the
//! triangle → face map (and, in `faces.rs`, the face → patch map), and the
//! self-intersection policy: a query names the faces it
//! starts and ends on, and hits on those faces are ignored; besides, the segment is
//! shortened at both ends by a length scaled to the scene (`1e-6` of its diagonal).
//! The triangle test is made watertight by a small tolerance on the barycentric
//! coordinates, so rays through shared edges (including the diagonal of a quad) never
//! slip between two triangles.
//!
//! obvhs's compressed wide BVH (the default) misses boxes along rays whose direction has
//! a zero (below 1e-7) component (axis-aligned rays, common between the patches of an
//! axis-aligned room): such components are nudged to ±1e-7 before its traversal, which
//! moves a ray by at most 1e-7 of its length. The scene may also be turned by a fixed
//! generic rotation before the build, every query turned with it. Which layout is
//! fastest and correct was measured with `ugo bench --layouts` (`docs/performance.md`).
//! Its traversal also drops every box that ends within [`NEAREST_BOX`] (an absolute
//! length, in the scene's metres) of the ray's origin, whatever the ray's own `tmin`: every
//! query's ray starts that far behind its origin, its `tmin` moved on to match.

mod between;
mod faces;
mod hull;
mod occluders;
mod packet;
mod shaft;

pub use between::SightTo;
pub use faces::{Faces, Landing, standoff};
pub use occluders::Occluders;
pub use packet::{PACKET, Segment};
pub use shaft::{Sight, SightFrom};

use crate::geometry::{ConvexPolygon, Mesh, Surface};
use glam::{DMat3, DVec3, Vec3A};
use obvhs::{
    BvhBuildParams,
    bvh2::{Bvh2, builder::build_bvh2_from_tris},
    cwbvh::{CwBvh, builder::build_cwbvh_from_tris},
    ray::{Ray, RayHit},
    triangle::Triangle,
};
use std::cell::Cell;
use std::sync::OnceLock;
use std::time::Duration;

/// Which BVH layout the queries run on.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct VisibilityOptions {
    /// The compressed wide BVH (CwBvh) rather than the binary BVH2.
    pub wide: bool,
    /// Build over the scene turned by a fixed rotation (axis-aligned faces then not aligned with
    /// the boxes).
    pub rotate: bool,
    /// obvhs's build quality.
    pub preset: BuildPreset,
}

/// The obvhs build presets that were measured.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum BuildPreset {
    /// obvhs's fastest build.
    Fast,
    /// obvhs's medium build.
    Medium,
    /// obvhs's slowest, best-quality build (the default).
    Slow,
}

impl Default for VisibilityOptions {
    fn default() -> Self {
        VisibilityOptions { wide: true, rotate: false, preset: BuildPreset::Slow }
    }
}

/// The BVH the queries traverse, in either layout.
enum Bvh {
    Binary(Bvh2),
    Wide(CwBvh),
}

/// A ray-casting structure over the faces of a mesh.
pub struct Visibility {
    bvh: Bvh,
    /// Triangles in the BVH's primitive order (rotated when `rotation` is not identity).
    triangles: Vec<Triangle>,
    /// Face of each triangle, same order.
    face_of: Vec<u32>,
    rotation: DMat3,
    epsilon: f64,
    /// The binary BVH of the shaft queries (`shaft.rs`), built on the first.
    shafts: OnceLock<Bvh2>,
    /// The surfaces' large convex pieces that hide whole shafts, when the surfaces are known.
    occluders: Option<Occluders>,
}

/// The first face hit by a ray.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Hit {
    /// The face hit.
    pub face: u32,
    /// Distance along the (unit) direction, m.
    pub distance: f64,
}

/// Sentinel for "no face to ignore".
pub const NO_FACE: u32 = u32::MAX;

/// The triangle that blocked a caller's last occlusion query, if any.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Blocker(Option<usize>);

/// obvhs's compressed wide traversal ignores boxes whose far side lies closer than this to
/// the ray's origin, m (its `cwbvh::node::EPSILON`): a flat box (a face of an axis-aligned
/// room) nearer than this would never be hit, so rays start this far back.
pub const NEAREST_BOX: f64 = 1e-4;

/// No blocker known yet.
pub const NO_BLOCKER: Blocker = Blocker(None);

impl Visibility {
    /// The default structure (CwBvh, slow build, no rotation) over the faces of `mesh`.
    pub fn build(mesh: &Mesh) -> Visibility {
        Visibility::build_with(mesh, VisibilityOptions::default())
    }

    /// The structure over the faces of `mesh` with the layout of `options`.
    pub fn build_with(mesh: &Mesh, options: VisibilityOptions) -> Visibility {
        let rotation = if options.rotate {
            DMat3::from_euler(glam::EulerRot::XYZ, 0.5123, 0.7331, 0.3179)
        } else {
            DMat3::IDENTITY
        };
        let mut seen = vec![false; mesh.faces];
        let (mut triangles, mut face_of) = (Vec::new(), Vec::new());
        for p in &mesh.patches {
            if std::mem::replace(&mut seen[p.face as usize], true) {
                continue;
            }
            for [a, b, c] in p.polygon.triangles() {
                let v = |x: DVec3| Vec3A::from((rotation * x).as_vec3());
                triangles.push(Triangle { v0: v(a), v1: v(b), v2: v(c) });
                face_of.push(p.face);
            }
        }
        let params = match options.preset {
            BuildPreset::Fast => BvhBuildParams::fast_build(),
            BuildPreset::Medium => BvhBuildParams::medium_build(),
            BuildPreset::Slow => BvhBuildParams::slow_build(),
        };
        let mut time = Duration::default();
        let (bvh, order) = if options.wide {
            let wide = build_cwbvh_from_tris(&triangles, params, &mut time);
            let order = wide.primitive_indices.clone();
            (Bvh::Wide(wide), order)
        } else {
            let binary = build_bvh2_from_tris(&triangles, params, &mut time);
            let order = binary.primitive_indices.clone();
            (Bvh::Binary(binary), order)
        };
        Visibility {
            bvh,
            triangles: order.iter().map(|&i| triangles[i as usize]).collect(),
            face_of: order.iter().map(|&i| face_of[i as usize]).collect(),
            rotation,
            epsilon: 1e-6 * mesh.extent(),
            shafts: OnceLock::new(),
            occluders: None,
        }
    }

    /// The default structure over the faces of `mesh`, meshed from `surfaces`, with their
    /// occluders (`occluders.rs`): shafts hidden behind a wall are then known without rays.
    pub fn build_for(surfaces: &[Surface], mesh: &Mesh) -> Visibility {
        let mut visibility = Visibility::build(mesh);
        visibility.occluders = Some(Occluders::of(surfaces, mesh));
        visibility
    }

    /// True when no face stands in the hull of `p` and the convex `polygon` (`p` in front of
    /// its plane), so that every segment from `p` to the polygon is clear
    /// (`Occluders::clear`); false when one may, or when the occluders are not known.
    pub fn hull_is_clear(&self, p: DVec3, polygon: &ConvexPolygon) -> bool {
        self.occluders.as_ref().is_some_and(|o| o.clear(p, polygon, self.epsilon))
    }

    /// True when the segment from `a` to `b` crosses no face other than `ignore`.
    pub fn visible(&self, a: DVec3, b: DVec3, ignore: [u32; 2]) -> bool {
        self.visible_cached(a, b, ignore, &mut Blocker::default())
    }

    /// [`Visibility::visible`] that first tries the triangle which blocked the caller's
    /// previous query (`blocker`, updated): neighbouring segments are often blocked by
    /// the same triangle, and one test then replaces a traversal.
    pub fn visible_cached(&self, a: DVec3, b: DVec3, ignore: [u32; 2], blocker: &mut Blocker) -> bool {
        self.segment(a, b).is_none_or(|ray| self.misses(&ray, ignore, blocker))
    }

    /// The ray of the segment from `a` to `b`, shortened at both ends by the scene's
    /// epsilon; none when the segment is too short to be blocked.
    fn segment(&self, a: DVec3, b: DVec3) -> Option<Ray> {
        let d = b - a;
        let length = d.length();
        (length > 2.0 * self.epsilon).then(|| self.ray(a, d / length, self.epsilon, length - self.epsilon))
    }

    /// [`Visibility::visible_cached`] with the blocker in a cell, for the `Fn` closures of
    /// a gather (`transfer::occlusion::cut_along_shadows`): one cell per worker.
    pub fn visible_shared(&self, a: DVec3, b: DVec3, ignore: [u32; 2], blocker: &Cell<Blocker>) -> bool {
        let mut last = blocker.get();
        let visible = self.visible_cached(a, b, ignore, &mut last);
        blocker.set(last);
        visible
    }

    /// True when the ray from `origin` along `direction` crosses no face other than
    /// `ignore`: it leaves the scene. The query stops at the first face it meets, where
    /// [`Visibility::closest_hit`] looks on for the nearest.
    pub fn escapes(&self, origin: DVec3, direction: DVec3, ignore: u32) -> bool {
        self.escapes_cached(origin, direction, ignore, &mut Blocker::default())
    }

    /// [`Visibility::escapes`] that first tries the triangle which blocked the caller's
    /// previous query (`blocker`, updated), as [`Visibility::visible_cached`].
    pub fn escapes_cached(&self, origin: DVec3, direction: DVec3, ignore: u32, blocker: &mut Blocker) -> bool {
        let ray = self.ray(origin, direction.normalize(), self.epsilon, f32::INFINITY as f64);
        self.misses(&ray, [ignore, ignore], blocker)
    }

    /// True when `ray` meets no face other than `ignore`, trying `blocker` first.
    fn misses(&self, ray: &Ray, ignore: [u32; 2], blocker: &mut Blocker) -> bool {
        if self.blocks(*blocker, ray, ignore) {
            return false;
        }
        let first = self.first_blocker(ray, ignore);
        if first.is_some() {
            blocker.0 = first;
        }
        first.is_none()
    }

    /// True when the triangle of `blocker` meets `ray` and is not on a face of `ignore`.
    fn blocks(&self, blocker: Blocker, ray: &Ray, ignore: [u32; 2]) -> bool {
        blocker.0.is_some_and(|id| self.meets(id, ray, ignore) < f32::INFINITY)
    }

    /// The distance along `ray` to triangle `id`, infinite when it is missed or lies on a
    /// face of `ignore`.
    #[inline(always)]
    fn meets(&self, id: usize, ray: &Ray, ignore: [u32; 2]) -> f32 {
        let face = self.face_of[id];
        if face == ignore[0] || face == ignore[1] { f32::INFINITY } else { intersect(&self.triangles[id], ray) }
    }

    /// The first triangle the traversal finds along `ray` that is not on a face of `ignore`.
    fn first_blocker(&self, ray: &Ray, ignore: [u32; 2]) -> Option<usize> {
        let mut hit = None;
        let test = |ray: &Ray, id: usize| {
            let t = self.meets(id, ray, ignore);
            if t < f32::INFINITY {
                hit = Some(id);
            }
            t
        };
        match &self.bvh {
            Bvh::Binary(binary) => binary.ray_traverse_miss(*ray, test),
            Bvh::Wide(wide) => wide.ray_traverse_miss(*ray, test),
        };
        hit
    }

    /// The first face along `origin + t·direction`, `t > 0`, other than `ignore`.
    pub fn closest_hit(&self, origin: DVec3, direction: DVec3, ignore: u32) -> Option<Hit> {
        let ray = self.ray(origin, direction.normalize(), self.epsilon, f32::INFINITY as f64);
        let test = |ray: &Ray, id: usize| {
            if self.face_of[id] == ignore { f32::INFINITY } else { intersect(&self.triangles[id], ray) }
        };
        let mut hit = RayHit::none();
        let found = match &self.bvh {
            Bvh::Binary(binary) => binary.ray_traverse(ray, &mut hit, test),
            Bvh::Wide(wide) => wide.ray_traverse(ray, &mut hit, test),
        };
        found.then(|| Hit { face: self.face_of[hit.primitive_id as usize], distance: hit.t as f64 - NEAREST_BOX })
    }

    /// The ray of a query, started [`NEAREST_BOX`] behind `origin` with its `tmin` and
    /// `tmax` moved on by as much: the wide traversal drops boxes that end nearer than that
    /// to the ray's origin, which would lose faces just beyond `origin`. Hit distances
    /// along it are [`NEAREST_BOX`] longer than from `origin`.
    fn ray(&self, origin: DVec3, direction: DVec3, tmin: f64, tmax: f64) -> Ray {
        let o = Vec3A::from((self.rotation * (origin - direction * NEAREST_BOX)).as_vec3());
        let mut d = Vec3A::from((self.rotation * direction).as_vec3());
        if matches!(self.bvh, Bvh::Wide(_)) {
            // obvhs's wide traversal misses boxes along exactly axis-aligned rays.
            d = Vec3A::select(d.abs().cmplt(Vec3A::splat(1e-7)), Vec3A::splat(1e-7).copysign(d), d);
        }
        Ray::new(o, d, (tmin + NEAREST_BOX) as f32, (tmax + NEAREST_BOX) as f32)
    }
}

/// Barycentric slack that closes the cracks between triangles sharing an edge.
const EDGE_SLACK: f32 = 1e-5;

/// Möller–Trumbore with a slack on the barycentric coordinates; distance or infinity.
#[inline(always)]
fn intersect(tri: &Triangle, ray: &Ray) -> f32 {
    let (e1, e2) = (tri.v1 - tri.v0, tri.v2 - tri.v0);
    let p = ray.direction.cross(e2);
    let det = e1.dot(p);
    if det.abs() < 1e-20 {
        return f32::INFINITY;
    }
    let inv = 1.0 / det;
    let s = ray.origin - tri.v0;
    let u = s.dot(p) * inv;
    let q = s.cross(e1);
    let v = ray.direction.dot(q) * inv;
    let t = e2.dot(q) * inv;
    let inside = u >= -EDGE_SLACK && v >= -EDGE_SLACK && u + v <= 1.0 + EDGE_SLACK;
    if inside && t > ray.tmin && t < ray.tmax { t } else { f32::INFINITY }
}
