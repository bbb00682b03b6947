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
//! (`crate::transfer::occlusion::cut_along_shadows`) while the piece's unshadowed light
//! exceeds the caller's least (on a patch, [`SHADOW_SHARE`] of the whole opening's). A
//! uniform sky is thus exact
//! (`E = π L F`), and the error of a graded sky is of second order in the pieces' size.
//! A glazed opening multiplies each piece's luminance by the glazing's `τ(θ)` at the
//! incidence of the piece's direction on the opening (`glazing.rs`).

use super::{Glazing, Sky};
use crate::geometry::{ConvexPolygon, MAX_CLIPPED};
use crate::transfer::contour::projected_solid_angle;
use crate::transfer::occlusion::cut_along_shadows;
use crate::visibility::Sight;
use glam::DVec3;

/// A piece is cut while its diameter exceeds `ETA` times its distance from the point.
pub const ETA: f64 = 0.1;
/// Most levels of cutting for size.
pub const MAX_DEPTH: u32 = 8;
/// Where the opening's light is averaged over a patch, a piece crossed by a shadow edge is
/// cut further only while its unshadowed light exceeds this share of the whole opening's
/// [`unshadowed`] light at the point: each piece left uncut is off by at most that share,
/// in either direction, and is read at its four points. A reading (a probe, a grid point)
/// cuts every such piece down to the deepest level.
pub const SHADOW_SHARE: f64 = 1e-4;

/// How finely an opening's pieces are cut seen from a point: for size while a piece's
/// diameter exceeds `eta` times its distance, and along a shadow edge while a piece's
/// unshadowed light exceeds `shadow_share` of the whole opening's ([`unshadowed`]; 0: down
/// to the deepest level).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cuts {
    /// A piece is cut while its diameter exceeds this times its distance.
    pub eta: f64,
    /// A shadowed piece is cut while its light exceeds this share of the opening's.
    pub shadow_share: f64,
}

/// A reading's cuts (a probe, a grid point): [`ETA`], every shadow edge cut.
pub const READING: Cuts = Cuts { eta: ETA, shadow_share: 0.0 };

impl Cuts {
    /// The least unshadowed light (lx) of a shadowed piece that is still cut, at `p` facing
    /// the unit `n`.
    pub fn least(&self, sky: &Sky, opening: &Opening, p: DVec3, n: DVec3) -> f64 {
        match self.shadow_share > 0.0 {
            true => self.shadow_share * unshadowed(sky, opening, p, n),
            false => 0.0,
        }
    }
}

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
/// component. `sight` says whether the ray from `p` through a point of the opening leaves
/// the scene, and whether nothing stands before a whole piece (then no ray is traced
/// through it); a piece crossed by a shadow edge is cut further only while
/// its unshadowed illuminance exceeds `least` lx, and every piece is cut for size while its diameter
/// exceeds `eta` times its distance ([`ETA`] at a point; coarser where the light is
/// averaged anyway, over a patch). Returns the rays traced.
#[allow(clippy::too_many_arguments)]
pub fn through_window(
    eta: f64,
    sky: &Sky,
    opening: &Opening,
    p: DVec3,
    n: DVec3,
    sight: &dyn Sight,
    least: f64,
    visit: &mut dyn FnMut(DVec3, f64, Component),
) -> usize {
    let window = &opening.polygon;
    let size = window.diameter();
    if window.vertices().iter().all(|v| (*v - p).dot(n) <= 1e-12 * size) {
        return 0;
    }
    let smallest = 1e-12 * size * size;
    // the whole opening first: a shaft through a part cut from it is tested more loosely
    let clear = sight.clear(window);
    let mut rays = 0;
    if !clear && sight.hidden(window, &mut rays) {
        return rays;
    }
    for_each_part(window, p, n, &mut |piece, component| {
        let mut view = View { sky, opening, p, n, sight, least, component, visit: &mut *visit, rays: 0, smallest, eta };
        view.piece(piece, 0, clear);
        rays += view.rays;
    });
    rays
}

/// The illuminance (lx) the opening gives the plane of `p` (unit normal `n`) with nothing in
/// the way but the opening's own edges: per part above and below the horizontal plane
/// through `p`, its exact projected solid angle times the luminance seen towards its centre.
pub fn unshadowed(sky: &Sky, opening: &Opening, p: DVec3, n: DVec3) -> f64 {
    let mut e = 0.0;
    for_each_part(&opening.polygon, p, n, &mut |part, component| {
        let towards = (part.centroid() - p).normalize_or_zero();
        e += luminance_through(sky, opening, towards, component) * projected_solid_angle(p, n, part.vertices()).abs();
    });
    e
}

/// The outside's luminance seen through `opening` along the unit `towards` (cd/m²): the
/// sky's or the ground's, as `component` says, times the glass's `τ(θ)`.
fn luminance_through(sky: &Sky, opening: &Opening, towards: DVec3, component: Component) -> f64 {
    let outside = match component {
        Component::Sky => sky.sky_luminance(towards),
        Component::Ground => sky.ground_luminance(),
    };
    opening.glazing.map_or(outside, |g| outside * g.transmittance(towards.dot(opening.polygon.normal())))
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
    opening: &'a Opening,
    p: DVec3,
    n: DVec3,
    sight: &'a dyn Sight,
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
    /// `piece`, cut `depth` times; `clear` when nothing stands before it.
    fn piece(&mut self, piece: &ConvexPolygon, depth: u32, clear: bool) {
        if piece.area() <= self.smallest {
            return;
        }
        let clear = clear || self.sight.clear(piece);
        if !clear && self.sight.hidden(piece, &mut self.rays) {
            return;
        }
        if depth < MAX_DEPTH && piece.diameter() > self.eta * piece.distance_to(self.p) {
            piece.split().iter().for_each(|q| self.piece(q, depth + 1, clear));
            return;
        }
        let (sky, opening, p, n, component, least) =
            (self.sky, self.opening, self.p, self.n, self.component, self.least);
        let light = |part: &ConvexPolygon| {
            let towards = (part.centroid() - p).normalize_or_zero();
            let luminance = luminance_through(sky, opening, towards, component);
            (towards, luminance * projected_solid_angle(p, n, part.vertices()).abs())
        };
        let worth = |part: &ConvexPolygon| light(part).1 > least;
        let visit = &mut *self.visit;
        if clear {
            let (towards, e) = light(piece);
            visit(towards, e, component);
            return;
        }
        let sight = self.sight;
        self.rays += cut_along_shadows(piece, 0, &|x| sight.sees(x), &worth, &mut |part, seen| {
            let (towards, e) = light(part);
            visit(towards, e * seen, component);
        });
    }
}
