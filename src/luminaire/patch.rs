//! The patch-averaged direct illuminance of the luminaires, `E_s(i,d)`, with shadows.
//!
//! Point source at `s`: the flux onto patch `P` is `∫_{Ω_P} I(ω) V(ω) dω`. The patch is
//! cut recursively into quarters while a piece looks large from the source (diameter over
//! distance above [`ETA`]); each piece then contributes `I` towards its centroid times its
//! exact solid angle (`ConvexPolygon::solid_angle`) times the fraction of its four
//! stratified points that see the source. Pieces whose points and corners disagree lie on
//! a shadow edge and are cut further (`transfer::occlusion::cut_along_shadows`). An isotropic source is thus
//! exact, and in a closed room its patches intercept its whole flux to round-off. Its
//! light reflected by a plane mirror `M` comes alike from its image at `R s`, of intensity
//! `ρ_M I(R w)`, through `M` (`transfer::image`, `docs/mirrors.md`).
//!
//! Parallel light along `l` with normal illuminance `E_n`: each piece receives
//! `E_n cosθ A` times the fraction of its points from which a ray towards `−l` escapes the
//! scene, times the share `T` the glazed openings that ray crosses let through
//! (`sky::BeamGlass`; the mean of `V T` over the points where `T` differs among them). Each piece's light goes to the cell of the patch frame it arrives from.
//!
//! An opening: the patch is cut while it is large seen from the opening, and each piece
//! gets the sky and ground through it at its centroid (`crate::sky::through_window`),
//! piece of the opening by piece, each to the cell it arrives from.

use super::{Light, Source};
use crate::directions::DirectionSet;
use crate::geometry::{ConvexPolygon, Frame, Mesh, Patch};
use crate::sky::{BeamGlass, Opening, SHADOW_SHARE, Sky, through_window, unshadowed};
use crate::transfer::image::PlaneMirror;
use crate::transfer::occlusion::{cut_along_shadows, polygon_points};
use crate::visibility::{NO_FACE, SightFrom, Visibility};
use glam::DVec3;
use rayon::prelude::*;
use std::f64::consts::PI;

/// A piece is cut while its diameter exceeds `ETA` times its distance from the source.
pub const ETA: f64 = 0.15;
/// Most levels of cutting for size.
pub const MAX_DEPTH: u32 = 8;
/// A patch is cut while its diameter exceeds `WINDOW_ETA` times its distance from an opening.
pub const WINDOW_ETA: f64 = 0.25;
/// Most levels of cutting a patch for an opening.
pub const WINDOW_DEPTH: u32 = 3;
/// Seen from a piece of a patch, a piece of an opening is cut while its diameter exceeds
/// `OPENING_ETA` times its distance (`crate::sky::through_window`; a probe's is
/// `crate::sky::ETA`).
pub const OPENING_ETA: f64 = 0.3;

/// The luminaires' direct light on the patches.
#[derive(Debug, Clone, PartialEq)]
pub struct DirectLight {
    /// `D(i,d) = E_s(i,d)/π` per (patch, cell), flat `i·K + d`: the units of `G x`.
    pub arriving: Vec<f64>,
    /// Flux of each source that lands on a patch, lm.
    pub intercepted: Vec<f64>,
    /// Occlusion rays traced.
    pub rays: usize,
    /// Per patch, the flux (lm) below which a piece crossed by a shadow edge was not cut
    /// further (`patch_lights`); 0, or no entry, where every edge was cut
    /// [`SHADOW_DEPTH`](crate::transfer::occlusion::SHADOW_DEPTH) levels deep. The light of
    /// some of the sources integrated with the same limits is exactly their share of this
    /// light (each source's pieces are cut on their own).
    pub least: Vec<f64>,
}

/// The direct light of `sources` on every patch of `mesh`, binned by `directions`, every
/// shadow edge cut down to the flux `least[i]` on patch `i` (every edge
/// [`SHADOW_DEPTH`](crate::transfer::occlusion::SHADOW_DEPTH) levels deep when `least` is
/// empty; [`DirectLight::least`] gives the limits another integration used), with the point
/// sources' images in `mirrors`.
pub fn direct_light(
    sources: &[Source],
    mesh: &Mesh,
    visibility: &Visibility,
    directions: &DirectionSet,
    least: &[f64],
    mirrors: &[PlaneMirror],
) -> DirectLight {
    let per_patch = patch_lights(sources, &mesh.patches, visibility, directions, least, mirrors);
    let mut light =
        DirectLight { arriving: Vec::with_capacity(mesh.len() * directions.len()), ..DirectLight::none(sources) };
    per_patch.iter().for_each(|p| light.add(p));
    light
}

/// The direct light on one patch: `D(d)` per cell and the flux of each source, lm.
#[derive(Debug, Clone, PartialEq)]
pub struct PatchLight {
    /// `D(d)` per cell of the patch, in the units of `G x` (`E = π Σ_d D(d)`).
    pub arriving: Vec<f64>,
    /// Flux of each source that lands on the patch, lm.
    pub intercepted: Vec<f64>,
    /// Occlusion rays traced.
    pub rays: usize,
    /// The flux below which its shadowed pieces were not cut further, lm (0: every edge).
    pub least: f64,
}

impl DirectLight {
    /// No patch yet, for `sources`.
    pub fn none(sources: &[Source]) -> DirectLight {
        DirectLight { arriving: Vec::new(), intercepted: vec![0.0; sources.len()], rays: 0, least: Vec::new() }
    }

    /// Appends the light of one more patch.
    pub fn add(&mut self, patch: &PatchLight) {
        self.arriving.extend_from_slice(&patch.arriving);
        self.intercepted.iter_mut().zip(&patch.intercepted).for_each(|(t, f)| *t += f);
        self.rays += patch.rays;
        self.least.push(patch.least);
    }
}

/// The direct light of `sources` on each of `patches` (whose faces are those of
/// `visibility`), in parallel. A piece of patch `i` crossed by a shadow edge is cut further
/// only while the flux it would receive unshadowed from one source, undimmed
/// (`Source::dimmed`), exceeds `least[i]`, lm (every piece when `least` is empty); below
/// that its lit fraction is that of its four points. A patch with no exposed area (inside a
/// solid) takes none: what its pieces would catch through gaps its points miss counts as
/// escaped (`readout::energy`). A point source's light reflected by a plane mirror of
/// `mirrors` arrives from its image (`docs/mirrors.md`); it is not in the source's
/// intercepted flux.
pub fn patch_lights(
    sources: &[Source],
    patches: &[Patch],
    visibility: &Visibility,
    directions: &DirectionSet,
    least: &[f64],
    mirrors: &[PlaneMirror],
) -> Vec<PatchLight> {
    let k = directions.len();
    patches
        .par_iter()
        .enumerate()
        .map(|(i, patch)| {
            let mut out = vec![0.0; k];
            let least = least.get(i).copied().unwrap_or(0.0);
            if patch.exposed <= 0.0 {
                return PatchLight { arriving: out, intercepted: vec![0.0; sources.len()], rays: 0, least };
            }
            let mut onto =
                Onto { patch, frame: patch.frame(), visibility, directions, least, out: &mut out, flux: 0.0, rays: 0 };
            let intercepted = sources
                .iter()
                .map(|source| {
                    onto.flux = 0.0;
                    onto.least = least * source.dimmed;
                    match &source.light {
                        Light::Point { position, .. } => {
                            if (*position - patch.polygon.vertices()[0]).dot(patch.normal) > 0.0 {
                                let s = *position;
                                let sees = |x: DVec3| visibility.visible(s, x, [NO_FACE, patch.face]);
                                onto.point(s, &|w| source.intensity(w), &sees, &patch.polygon, 0);
                            }
                            mirrors.iter().for_each(|mirror| onto.mirrored(source, *position, mirror));
                        }
                        Light::Parallel { direction, illuminance, glass } => {
                            let cos = -direction.dot(patch.normal);
                            if cos > 0.0 {
                                onto.parallel(*direction, glass, illuminance * cos, &patch.polygon);
                            }
                        }
                        Light::Window { window, sky } => onto.window(sky, window, &patch.polygon, 0),
                    }
                    onto.flux
                })
                .collect();
            let rays = onto.rays;
            out.iter_mut().for_each(|d| *d = patch.per_exposed_area(*d) / PI);
            PatchLight { arriving: out, intercepted, rays, least }
        })
        .collect()
}

/// The light of one source onto one patch, accumulated per cell (as flux, lm).
struct Onto<'a> {
    patch: &'a Patch,
    frame: Frame,
    visibility: &'a Visibility,
    directions: &'a DirectionSet,
    /// Flux below which a shadowed piece is not cut further, lm: the patch's limit times
    /// the dimming of the source being integrated.
    least: f64,
    out: &'a mut [f64],
    flux: f64,
    rays: usize,
}

impl Onto<'_> {
    /// The light of a point at `s` of intensity `intensity(w)` towards the world direction
    /// `w`, seen from the points `sees` says see it, onto `piece`.
    fn point(
        &mut self,
        s: DVec3,
        intensity: &dyn Fn(DVec3) -> f64,
        sees: &dyn Fn(DVec3) -> bool,
        piece: &ConvexPolygon,
        depth: u32,
    ) {
        if depth < MAX_DEPTH && piece.diameter() > ETA * (piece.centroid() - s).length() {
            piece.split().iter().for_each(|p| self.point(s, intensity, sees, p, depth + 1));
            return;
        }
        let least = self.least;
        let worth = |part: &ConvexPolygon| {
            let w = (part.centroid() - s).normalize();
            intensity(w) * part.solid_angle(s) > least
        };
        let rays = cut_along_shadows(piece, depth, &sees, &worth, &mut |part, seen| {
            let w = (part.centroid() - s).normalize();
            self.add(-w, intensity(w) * part.solid_angle(s) * seen);
        });
        self.rays += rays;
    }

    /// The light of the point source `source` at `s` reflected by the plane `mirror`: its
    /// image at `R s`, of intensity `ρ_M I(R w)`, seen through the mirror. It arrives on the
    /// patch, but it is not the source's intercepted flux.
    fn mirrored(&mut self, source: &Source, s: DVec3, mirror: &PlaneMirror) {
        let image = mirror.reflect(s);
        let corner = self.patch.polygon.vertices()[0];
        if mirror.height(s) <= 0.0 || !mirror.in_front(self.patch) || (image - corner).dot(self.patch.normal) <= 0.0 {
            return;
        }
        let (visibility, face) = (self.visibility, self.patch.face);
        let intensity = |w: DVec3| mirror.reflectance * source.intensity(mirror.reflect_direction(w));
        let sees = |x: DVec3| mirror.passes(visibility, x, face, image, NO_FACE);
        let flux = self.flux;
        let polygon = self.patch.polygon;
        self.point(image, &intensity, &sees, &polygon, 0);
        self.flux = flux;
    }

    /// Parallel light of `normal_share = E_n cos θ` along `direction` onto `piece`, each lit
    /// part times the share `glass` lets through there.
    fn parallel(&mut self, direction: DVec3, glass: &BeamGlass, normal_share: f64, piece: &ConvexPolygon) {
        let (visibility, face) = (self.visibility, self.patch.face);
        let escapes = |x: DVec3| visibility.escapes(x, -direction, face);
        let mut flux = 0.0;
        let least = self.least;
        let worth = |part: &ConvexPolygon| normal_share * part.area() > least;
        let rays = cut_along_shadows(piece, 0, &escapes, &worth, &mut |part, seen| {
            let through = glass.over_points(&polygon_points(part), -direction, seen, &escapes);
            flux += normal_share * part.area() * through
        });
        self.rays += rays;
        self.add(-direction, flux);
    }

    /// The sky and ground through `window`: `piece` is cut into quarters while it is large
    /// seen from the opening (diameter over distance above [`WINDOW_ETA`], at most
    /// [`WINDOW_DEPTH`] times), and each piece gets the light at its centroid, its shadow
    /// edges cut while a piece of the opening holds [`SHADOW_SHARE`] of its light.
    fn window(&mut self, sky: &Sky, window: &Opening, piece: &ConvexPolygon, depth: u32) {
        let c = piece.centroid();
        if depth < WINDOW_DEPTH && piece.diameter() > WINDOW_ETA * window.polygon.distance_to(c) {
            piece.split().iter().for_each(|p| self.window(sky, window, p, depth + 1));
            return;
        }
        let (visibility, face, normal, area) = (self.visibility, self.patch.face, self.patch.normal, piece.area());
        let sight = SightFrom::new(visibility, c, normal, face);
        let least = (self.least / area).max(SHADOW_SHARE * unshadowed(sky, window, c, normal));
        let mut arrivals = Vec::new();
        let mut arrive = |towards, e, _| arrivals.push((towards, e * area));
        self.rays += through_window(OPENING_ETA, sky, window, c, normal, &sight, least, &mut arrive);
        arrivals.into_iter().for_each(|(towards, flux)| self.add(towards, flux));
    }

    /// `flux` arriving from the world direction `towards_source`.
    fn add(&mut self, towards_source: DVec3, flux: f64) {
        if flux > 0.0 {
            let d = self.directions.lookup(self.frame.local(towards_source));
            self.out[d] += flux;
            self.flux += flux;
        }
    }
}
