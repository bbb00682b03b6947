//! The final gather: one more reflection evaluated at the hit point `q` itself with the
//! material's own luminance factor, `L(q, l) = Le + (1/π) ∫ ρ(l, l') L(q, l') cosθ' dω'`
//! (`design.md` §5), the incoming `L` read from the solved field. The reflection seen is
//! then as sharp as the material: a glossy lobe is not averaged over direction cells.
//!
//! The incoming light is split in two:
//! * **direct**: every self-emitting patch `j` contributes `Le_j F_{q→P_j} ρ̄_j`, `F` the
//!   exact contour-integral factor and `ρ̄_j` the mean of `ρ(l, l'_y) V(q, y)` over the
//!   kernel's four stratified points `y` of `P_j` (`transfer::occlusion`; on a Lambertian
//!   surface `ρ` times the visibility fraction): no noise from small lamps. Every luminaire
//!   gives its exact light at `q` in its exact direction (`luminaire::arriving_along`).
//! * **indirect**: `rays` directions importance-sampled from `ρ cosθ'` by the material's
//!   own sampler, from a shifted Hammersley set (`random::Stratified`); each adds its weight times
//!   `(L_j(m) − Le_j)/rays`, `L_j(m)` the stored luminance of the patch it hits in the cell
//!   pointing back at `q` (its emission was counted above). A mirror's single direction
//!   takes one ray and the whole `L_j(m)`: its direct part is empty.
//!
//! A transmitting two-sided surface also gathers on its back side (its sampler turns some
//! directions through). The patch pattern of the solution shows only through the light of
//! the second reflection onward.

use super::solved::Solved;
use crate::geometry::{Frame, NO_TWIN};
use crate::luminaire::{OPENING_ETA, arriving_along};
use crate::material::MaterialModel;
use crate::random::{Rng, Stratified};
use crate::transfer::contour::point_to_patch;
use crate::transfer::occlusion::{POINTS, sample_points};
use glam::DVec3;

/// The luminance leaving `patch` at `q` towards the unit direction `towards`, gathered.
pub fn final_gather(lit: &Solved, patch: usize, q: DVec3, towards: DVec3, rays: usize, rng: &mut Rng) -> f64 {
    let p = &lit.mesh.patches[patch];
    let frame = p.frame();
    let material = &lit.materials[p.material as usize];
    let l = frame.local(towards);
    let factor = |w: DVec3| material.luminance_factor(l, frame.local(w));
    let through = material.transmits() && p.twin != NO_TWIN;
    let sides: &[DVec3] = if through { &[frame.normal, -frame.normal] } else { &[frame.normal] };
    let direct: f64 = sides.iter().map(|&n| direct_light(lit, q, n, p.face, &factor)).sum();
    lit.mesh.emission[patch] + direct + indirect_light(lit, q, &frame, l, material, p.face, rays, rng)
}

/// The emitters' and luminaires' light arriving at `q` on the side facing `n` (ignoring
/// the face `face`), reflected by `factor(direction towards the light)`, cd/m².
fn direct_light(lit: &Solved, q: DVec3, n: DVec3, face: u32, factor: &impl Fn(DVec3) -> f64) -> f64 {
    let mut sum = 0.0;
    for &j in &lit.emitters {
        let s = &lit.mesh.patches[j as usize];
        let f = if s.face == face { 0.0 } else { point_to_patch(q, n, s) };
        if f <= 0.0 {
            continue;
        }
        let reflected: f64 = sample_points(s)
            .iter()
            .filter(|&&y| (y - q).dot(n) > 0.0 && lit.visibility.visible(q, y, [face, s.face]))
            .map(|&y| factor((y - q).normalize()))
            .sum();
        sum += lit.mesh.emission[j as usize] * f * reflected / POINTS as f64;
    }
    let mut arrive = |towards: DVec3, d: f64| sum += d * factor(towards);
    arriving_along(&lit.sources, &lit.visibility, q, n, face, OPENING_ETA, &mut arrive);
    sum
}

/// The light of the solved field's second reflection onward arriving at `q` and reflected
/// towards the local direction `l`: `rays` directions sampled by `material`, stratified.
#[allow(clippy::too_many_arguments)]
fn indirect_light(
    lit: &Solved,
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
        let [u, v] = points.point(r);
        let Some(sample) = material.sample(l, [rng.uniform(), u, v]) else { continue };
        let w = frame.world(sample.direction);
        if let Some((j, _)) = lit.hit_ignoring(q, w, face) {
            let counted = if sample.delta { 0.0 } else { lit.mesh.emission[j] };
            sum += sample.weight * (lit.flat(j, -w) - counted);
        }
    }
    sum / rays as f64
}
