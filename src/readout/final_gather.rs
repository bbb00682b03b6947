//! The final gather: one more reflection evaluated at the hit point `q` itself with the
//! material's own luminance factor, `L(q, l) = Le + (1/π) ∫ ρ(l, l') L(q, l') cosθ' dω'`
//! (`docs/design.md` §5), the incoming `L` read from the solved field. The reflection seen is
//! then as sharp as the material: a glossy lobe is not averaged over direction cells.
//!
//! The incoming light is split in two:
//! * **direct**: every self-emitting patch `j` contributes `Le_j F_{q→P_j} ρ̄_j`, `F` the
//!   exact contour-integral factor and `ρ̄_j` the mean of `ρ(l, l'_y) V(q, y)` over the
//!   kernel's four stratified points `y` of `P_j` (`transfer::occlusion`; on a Lambertian
//!   surface `ρ` times the visibility fraction): no noise from small lamps. Where `ρ` varies
//!   over `P_j` by more than 5 % of its mean (a lobe's highlight), `P_j` is cut into
//!   quarters, each with its own factor and points, up to four times. Every luminaire
//!   gives its exact light at `q` in its exact direction (`luminaire::arriving_along`).
//! * **indirect**: `rays` directions importance-sampled from `ρ cosθ'` by the material's
//!   own sampler, from a shifted three-dimensional Hammersley set (`random::Stratified`, its
//!   third coordinate choosing the sampler's component); each adds its weight times
//!   `(L_j(m) − Le_j)/rays`, `L_j(m)` the stored luminance of the patch it hits in the cell
//!   pointing back at `q` (its emission was counted above). A mirror's single direction
//!   takes one ray and the whole `L_j(m)`: its direct part is empty.
//!
//! A transmitting two-sided surface also gathers on its back side (its sampler turns some
//! directions through). The patch pattern of the solution shows only through the light of
//! the second reflection onward.

use crate::geometry::{ConvexPolygon, Frame, Mesh, NO_TWIN, Patch};
use crate::luminaire::{OPENING_ETA, Source, arriving_along};
use crate::material::MaterialModel;
use crate::random::{Rng, Stratified};
use crate::sky::Cuts;
use crate::transfer::contour::point_to_patch;
use crate::transfer::occlusion::{POINTS, polygon_points};
use crate::visibility::Visibility;
use glam::DVec3;

/// What a final gather reads of a solved scene: its patches, materials, self-emitting
/// patches and luminaires, and what a ray meets. A stored solution made ready for
/// rendering (`crate::render::Solved`) is one; the readouts of glossy surfaces read a
/// model's field through another (`glossy.rs`).
pub trait Surroundings {
    /// The patches whose stored luminance is read.
    fn mesh(&self) -> &Mesh;
    /// The ray caster over their faces.
    fn visibility(&self) -> &Visibility;
    /// The material model of `patch`.
    fn material(&self, patch: usize) -> &MaterialModel;
    /// The patches with a self-emission.
    fn emitters(&self) -> &[u32];
    /// The luminaires, whose direct light is added exactly.
    fn sources(&self) -> &[Source];
    /// The patch first met from `q` along the unit `w` (ignoring face `face`) and its
    /// stored luminance towards `q`, cd/m².
    fn met(&self, q: DVec3, w: DVec3, face: u32) -> Option<(usize, f64)>;
}

/// The luminance leaving `patch` at `q` towards the unit direction `towards`, gathered.
pub fn final_gather(
    lit: &impl Surroundings,
    patch: usize,
    q: DVec3,
    towards: DVec3,
    rays: usize,
    rng: &mut Rng,
) -> f64 {
    let p = &lit.mesh().patches[patch];
    let frame = p.frame();
    let material = lit.material(patch);
    let l = frame.local(towards);
    let factor = |w: DVec3| material.luminance_factor(l, frame.local(w));
    let through = material.transmits() && p.twin != NO_TWIN;
    let sides: &[DVec3] = if through { &[frame.normal, -frame.normal] } else { &[frame.normal] };
    let direct: f64 = sides.iter().map(|&n| direct_light(lit, q, n, p.face, &factor)).sum();
    lit.mesh().emission[patch] + direct + indirect(lit, patch, q, towards, rays, rng)
}

/// The indirect part of [`final_gather`] alone: the light of the field's second
/// reflection onward that `patch` reflects at `q` towards `towards`, over `rays` sampled
/// directions. Two calls with clones of one stream sample the same directions, so two
/// readings of the field can be compared ray by ray.
pub fn indirect(lit: &impl Surroundings, patch: usize, q: DVec3, towards: DVec3, rays: usize, rng: &mut Rng) -> f64 {
    let p = &lit.mesh().patches[patch];
    let frame = p.frame();
    indirect_light(lit, q, &frame, frame.local(towards), lit.material(patch), p.face, rays, rng)
}

/// The emitters' and luminaires' light arriving at `q` on the side facing `n` (ignoring
/// the face `face`), reflected by `factor(direction towards the light)`, cd/m².
fn direct_light(lit: &impl Surroundings, q: DVec3, n: DVec3, face: u32, factor: &impl Fn(DVec3) -> f64) -> f64 {
    let (mesh, visibility) = (lit.mesh(), lit.visibility());
    let mut sum = 0.0;
    for &j in lit.emitters() {
        let s = &mesh.patches[j as usize];
        if s.face != face && point_to_patch(q, n, s) > 0.0 {
            let sees = |y: DVec3| visibility.visible(q, y, [face, s.face]);
            sum += mesh.emission[j as usize] * reflected_factor(q, n, s, &s.polygon, 0, &sees, factor);
        }
    }
    let mut arrive = |towards: DVec3, d: f64| sum += d * factor(towards);
    arriving_along(lit.sources(), visibility, q, n, face, PIXEL, &mut arrive);
    sum
}

/// Most times a piece of an emitter is cut into quarters where the luminance factor varies
/// over it.
const LOBE_DEPTH: u32 = 4;

/// A pixel's cuts of an opening: pieces of [`OPENING_ETA`], every shadow edge cut.
const PIXEL: Cuts = Cuts { eta: OPENING_ETA, shadow_share: 0.0 };

/// A piece is cut while the luminance factor at its four points spreads by more than this
/// fraction of their mean.
const LOBE_SPREAD: f64 = 0.05;

/// `F_{q→piece} · mean_y ρ(y) V(q, y)` over the four points `y` of `piece` (of emitter `s`,
/// cut `depth` times), the piece cut into quarters while `factor` varies over it (the
/// highlight of a lobe narrower than the piece); `ρ(y) = factor(direction to y)`.
fn reflected_factor(
    q: DVec3,
    n: DVec3,
    s: &Patch,
    piece: &ConvexPolygon,
    depth: u32,
    sees: &impl Fn(DVec3) -> bool,
    factor: &impl Fn(DVec3) -> f64,
) -> f64 {
    let points = polygon_points(piece);
    let rho = points.map(|y| if (y - q).dot(n) > 0.0 { factor((y - q).normalize()) } else { 0.0 });
    let (low, high) = rho.iter().fold((f64::INFINITY, 0.0_f64), |(l, h), &r| (l.min(r), h.max(r)));
    if depth < LOBE_DEPTH && high - low > LOBE_SPREAD * rho.iter().sum::<f64>() / POINTS as f64 {
        return piece.split().iter().map(|part| reflected_factor(q, n, s, part, depth + 1, sees, factor)).sum();
    }
    let seen: f64 = points.iter().zip(rho).filter(|&(&y, r)| r > 0.0 && sees(y)).map(|(_, r)| r).sum();
    if seen <= 0.0 {
        return 0.0;
    }
    let f = if depth == 0 { point_to_patch(q, n, s) } else { point_to_patch(q, n, &Patch { polygon: *piece, ..*s }) };
    f * seen / POINTS as f64
}

/// The light of the solved field's second reflection onward arriving at `q` and reflected
/// towards the local direction `l`: `rays` directions sampled by `material`, stratified.
#[allow(clippy::too_many_arguments)]
fn indirect_light(
    lit: &impl Surroundings,
    q: DVec3,
    frame: &Frame,
    l: DVec3,
    material: &MaterialModel,
    face: u32,
    rays: usize,
    rng: &mut Rng,
) -> f64 {
    let rays = if material.is_delta() { 1 } else { rays.max(1) };
    let points = Stratified::new(rays, rng);
    let mut sum = 0.0;
    for r in 0..rays {
        let [u, v, choice] = points.point3(r);
        let Some(sample) = material.sample(l, [choice, u, v]) else { continue };
        if let Some((j, luminance)) = lit.met(q, frame.world(sample.direction), face) {
            let counted = if sample.delta { 0.0 } else { lit.mesh().emission[j] };
            sum += sample.weight * (luminance - counted);
        }
    }
    sum / rays as f64
}
