//! The light a receiving point gets through an opening: the sky component (sky seen
//! through it) and the externally reflected component (the ground seen through it).
//!
//! At a point `p` with unit normal `n`, the opening's polygon is clipped to the half-space
//! in front of `p`, cut into triangles and split by the horizontal plane through `p`: the
//! part above looks at the sky, the part below at the ground. Each part is cut into
//! quarters while a piece looks large from `p` (diameter over distance above [`ETA`], at
//! most [`MAX_DEPTH`] times); a piece then gives `E = L(l_c) · ∫ cos θ dω` with `l_c` the
//! direction of its centroid and the projected solid angle exact (Lambert's contour
//! integral, `crate::transfer::contour`), times the fraction of its points from which the
//! ray through them leaves the scene (`sees`), pieces on a shadow edge cut further
//! (`crate::transfer::occlusion::cut_along_shadows`). A uniform sky is thus exact
//! (`E = π L F`), and the error of a graded sky is of second order in the pieces' size.
//! A glazed opening multiplies each piece's luminance by the glazing's `τ(θ)` at the
//! incidence of the piece's direction on the opening (`glazing.rs`).

use super::{Glazing, Sky};
use crate::geometry::{ConvexPolygon, MAX_CLIPPED};
use crate::transfer::contour::projected_solid_angle;
use crate::transfer::occlusion::cut_along_shadows;
use glam::DVec3;

/// A piece is cut while its diameter exceeds `ETA` times its distance from the point.
pub const ETA: f64 = 0.1;
/// Most levels of cutting for size.
pub const MAX_DEPTH: u32 = 8;

/// An opening: a parallelogram (or triangle) in the surfaces, glazed or not.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Opening {
    /// The opening's polygon, m.
    pub polygon: ConvexPolygon,
    /// The glass over it, if any: the outside is seen times `τ(θ)`.
    pub glazing: Option<Glazing>,
}

/// Which part of the outside a piece of the opening shows.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Component {
    /// The sky, above the horizon: the sky component SC.
    Sky,
    /// The ground, below the horizon: the externally reflected component ERC.
    Ground,
}

/// Hands `visit` every piece of the opening `window` seen from `p` (unit normal `n`): the unit
/// direction towards it, the illuminance it gives on the plane of `p` (lx) and its
/// component. `sees(x)` says whether the ray from `p` through the point `x` of the
/// opening leaves the scene; a piece crossed by a shadow edge is cut further only while
/// its unshadowed illuminance exceeds `least` lx, and every piece is cut for size while its
/// diameter exceeds `eta` times its distance ([`ETA`] at a point; coarser where the light
/// is averaged anyway, over a patch). Returns the rays traced.
#[allow(clippy::too_many_arguments)]
pub fn through_window(
    eta: f64,
    sky: &Sky,
    opening: &Opening,
    p: DVec3,
    n: DVec3,
    sees: &dyn Fn(DVec3) -> bool,
    least: f64,
    visit: &mut dyn FnMut(DVec3, f64, Component),
) -> usize {
    let window = &opening.polygon;
    let glazing = opening.glazing.map(|g| (g, window.normal()));
    let size = window.diameter();
    if window.vertices().iter().all(|v| (*v - p).dot(n) <= 1e-12 * size) {
        return 0;
    }
    let smallest = 1e-12 * size * size;
    let mut rays = 0;
    for_each_part(window, p, n, &mut |piece, component| {
        let mut view = View { sky, glazing, p, n, sees, least, component, visit: &mut *visit, rays: 0, smallest, eta };
        view.piece(piece, 0);
        rays += view.rays;
    });
    rays
}

/// Hands `visit` the parts of `window` in front of `p` (unit normal `n`), cut into triangles
/// and at the horizontal plane through `p`: each part with the component it shows.
pub(super) fn for_each_part(
    window: &ConvexPolygon,
    p: DVec3,
    n: DVec3,
    visit: &mut dyn FnMut(&ConvexPolygon, Component),
) {
    let mut front = [DVec3::ZERO; MAX_CLIPPED];
    let count = window.clip_above(p, n, &mut front);
    for i in 1..count.saturating_sub(1) {
        let triangle = ConvexPolygon::triangle(front[0], front[i], front[i + 1]);
        for (normal, component) in [(DVec3::Y, Component::Sky), (-DVec3::Y, Component::Ground)] {
            let mut part = [DVec3::ZERO; MAX_CLIPPED];
            let m = triangle.clip_above(p, normal, &mut part);
            if m >= 3 {
                visit(&ConvexPolygon::from_slice(&part[..m]), component);
            }
        }
    }
}

/// One component of one triangle of the opening, seen from one point.
struct View<'a, 'v> {
    sky: &'a Sky,
    /// The glass and the opening's unit normal.
    glazing: Option<(Glazing, DVec3)>,
    p: DVec3,
    n: DVec3,
    sees: &'a dyn Fn(DVec3) -> bool,
    least: f64,
    component: Component,
    visit: &'v mut dyn FnMut(DVec3, f64, Component),
    rays: usize,
    /// Pieces below this area (m²) are empty: a clip that left only an edge.
    smallest: f64,
    /// A piece is cut while its diameter exceeds `eta` times its distance.
    eta: f64,
}

impl View<'_, '_> {
    fn piece(&mut self, piece: &ConvexPolygon, depth: u32) {
        if piece.area() <= self.smallest {
            return;
        }
        if depth < MAX_DEPTH && piece.diameter() > self.eta * piece.distance_to(self.p) {
            piece.split().iter().for_each(|q| self.piece(q, depth + 1));
            return;
        }
        let (sky, p, n, component, least) = (self.sky, self.p, self.n, self.component, self.least);
        let glazing = self.glazing;
        let light = |part: &ConvexPolygon| {
            let towards = (part.centroid() - p).normalize_or_zero();
            let outside = match component {
                Component::Sky => sky.sky_luminance(towards),
                Component::Ground => sky.ground_luminance(),
            };
            let luminance = glazing.map_or(outside, |(g, normal)| outside * g.transmittance(towards.dot(normal)));
            (towards, luminance * projected_solid_angle(p, n, part.vertices()).abs())
        };
        let worth = |part: &ConvexPolygon| light(part).1 > least;
        let visit = &mut *self.visit;
        self.rays += cut_along_shadows(piece, 0, self.sees, &worth, &mut |part, seen| {
            let (towards, e) = light(part);
            visit(towards, e * seen, component);
        });
    }
}
