//! Backward ray tracing (`docs/design.md` §4): Monte Carlo path tracing from the eye with the
//! continuous materials, an unbiased estimate of `L = Σ_n Kⁿ L0` along a ray with no
//! discretization at all.
//!
//! At every surface point the path gathers the emitters directly (next-event estimation:
//! a point chosen by flux, a shadow ray) and continues in a direction sampled from the
//! material; light found both ways is weighted by the power heuristic of the two
//! densities (Veach & Guibas, SIGGRAPH 1995), so glossy lobes and small sources both
//! converge. From the third reflection on, Russian roulette ends a path with probability
//! `1 − min(β, 0.95)` and divides the survivors' throughput `β` by the survival chance.
//! `max_order = n` keeps only light reflected at most `n` times: the truncated Neumann sum
//! `Σ_{m≤n} Kᵐ L0`. Luminaires are gathered exactly at every vertex (`luminaires.rs`);
//! their light, reflected once in `L0`, is kept at the vertices up to `n`. So is the sky
//! through the openings (`openings.rs`): sampled towards an opening at every vertex, and
//! met by a scattered ray that leaves the scene through one, the two weighted by the
//! power heuristic (only the first at the last vertex kept). A camera sees the sky
//! through an opening and a luminaire's luminous opening directly, as the render does.

use super::openings::Openings;
use super::world::{Cast, World};
use crate::geometry::Frame;
use crate::material::MaterialModel;
use crate::random::Rng;
use crate::visibility::NO_FACE;
use glam::DVec3;
use std::f64::consts::FRAC_1_PI;

/// The reflection from which Russian roulette may end a path.
pub const ROULETTE_FROM: usize = 3;

/// Paths are cut after this many reflections whatever the roulette says (it only matters
/// for a closed scene of reflectance 1, which has no finite solution).
pub const LONGEST_PATH: usize = 100_000;

/// What the estimators are asked for.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TraceOptions {
    /// Every random stream is keyed by this seed and the sample's index.
    pub seed: u64,
    /// Keep only light reflected at most this many times (`None`: every order).
    pub max_order: Option<usize>,
}

impl Default for TraceOptions {
    fn default() -> Self {
        TraceOptions { seed: 1, max_order: None }
    }
}

/// Where a path starts.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Start {
    /// The first ray's origin, m.
    pub origin: DVec3,
    /// Unit direction of the first ray.
    pub direction: DVec3,
    /// The face `origin` lies on ([`NO_FACE`] for none).
    pub ignore: u32,
    /// The density per solid angle with which `direction` was drawn, when the caller also
    /// samples the emitters from `origin` (the emission met first is then weighted against
    /// that); `None` for a camera ray.
    pub drawn: Option<f64>,
    /// A camera's ray: it sees the luminaires' luminous openings and the sky through an
    /// opening directly (a probe's luminance is that of the first surface).
    pub camera: bool,
}

impl Start {
    /// A ray from an eye in free space.
    pub fn eye(origin: DVec3, direction: DVec3) -> Start {
        Start { origin, direction, ignore: NO_FACE, drawn: None, camera: false }
    }

    /// A camera's ray from an eye in free space.
    pub fn camera(origin: DVec3, direction: DVec3) -> Start {
        Start { camera: true, ..Start::eye(origin, direction) }
    }
}

/// One path's estimate of the luminance arriving at `start.origin` from `start.direction`
/// (that is, leaving the first surface towards the origin), cd/m²; `rays` counts the rays.
pub fn luminance_along(world: &World, start: Start, rng: &mut Rng, options: &TraceOptions, rays: &mut u64) -> f64 {
    let mesh = &world.mesh;
    let last = options.max_order.unwrap_or(LONGEST_PATH).min(LONGEST_PATH);
    let (mut origin, mut direction, mut ignore) = (start.origin, start.direction, start.ignore);
    let (mut beta, mut total) = (1.0, 0.0);
    // density of the direction just sampled, None after the eye or a mirror
    let mut scattered = start.drawn;
    if start.camera {
        *rays += 1;
        if let Some(luminance) = world.luminaires.seen(&world.visibility, origin, direction) {
            return luminance;
        }
    }
    for order in 0..=last {
        *rays += 1;
        let hit = match world.cast(origin, direction, ignore) {
            Cast::Lands(hit) => hit,
            Cast::Absorbed => break,
            Cast::Escapes => {
                // The sky through an opening lights the last vertex or the probe; a camera
                // sees it directly.
                if (order > 0 || start.drawn.is_some() || start.camera)
                    && let Some(seen) = world.openings.seen(origin, direction)
                {
                    let weight = scattered.map_or(1.0, |pdf| power_heuristic(pdf, seen.pdf));
                    total += beta * seen.luminance * weight;
                }
                break;
            }
        };
        let emitted = mesh.emission[hit.patch];
        if emitted > 0.0 {
            let weight = match scattered {
                None => 1.0,
                Some(pdf) => {
                    let light = world.emitters.pdf_towards(mesh, hit.patch, origin, hit.point);
                    power_heuristic(pdf, light)
                }
            };
            total += beta * emitted * weight;
        }
        let patch = &mesh.patches[hit.patch];
        let material = world.material(hit.patch);
        let frame = patch.frame();
        let out = frame.local(-direction);
        if !material.is_delta() {
            total += beta * world.luminaires.reflected(&world.visibility, material, &frame, hit.point, patch.face, out);
            if !world.openings.is_empty() {
                let vertex = Vertex { material, frame: &frame, point: hit.point, face: patch.face, out };
                total += beta * sky_reflected(world, &vertex, order < last, rng.uniform3(), rays);
            }
        }
        if order == last {
            break;
        }
        if !material.is_delta()
            && let Some(light) = world.emitters.sample_towards(mesh, hit.point, rng.uniform3())
        {
            let l_in = frame.local(light.direction);
            let rho = material.luminance_factor(out, l_in);
            if rho > 0.0 {
                *rays += 1;
                if world.visibility.visible(hit.point, light.point, [patch.face, light.face]) {
                    let weight = power_heuristic(light.pdf, material.pdf(out, l_in));
                    total += beta * rho * l_in.z.abs() * FRAC_1_PI * light.luminance / light.pdf * weight;
                }
            }
        }
        let Some(s) = material.sample(out, rng.uniform3()) else { break };
        beta *= s.weight;
        if beta <= 0.0 || !beta.is_finite() {
            break;
        }
        if order + 1 >= ROULETTE_FROM {
            let survive = beta.min(0.95);
            if rng.uniform() >= survive {
                break;
            }
            beta /= survive;
        }
        scattered = (!s.delta).then_some(s.pdf);
        origin = hit.point;
        direction = frame.world(s.direction);
        ignore = patch.face;
    }
    total
}

/// A path's vertex: where it is, on what, leaving towards the local `out`.
struct Vertex<'a> {
    material: &'a MaterialModel,
    frame: &'a Frame,
    point: DVec3,
    face: u32,
    out: DVec3,
}

/// Next-event estimation of the sky through the openings at a vertex: a sampled point of
/// an opening, its light reflected towards the vertex's `out`, cd/m², weighted by the power
/// heuristic against the material's own sampling when the path also continues from here
/// (`weighted`).
fn sky_reflected(world: &World, at: &Vertex, weighted: bool, u: [f64; 3], rays: &mut u64) -> f64 {
    let Some(light) = world.openings.sample_towards(at.point, u) else { return 0.0 };
    let l_in = at.frame.local(light.direction);
    let rho = at.material.luminance_factor(at.out, l_in);
    if rho <= 0.0 || light.luminance <= 0.0 {
        return 0.0;
    }
    *rays += 1;
    if !Openings::clear(&world.visibility, at.point, light.direction, at.face) {
        return 0.0;
    }
    let weight = if weighted { power_heuristic(light.pdf, at.material.pdf(at.out, l_in)) } else { 1.0 };
    rho * l_in.z.abs() * FRAC_1_PI * light.luminance / light.pdf * weight
}

/// The power heuristic `p²/(p² + q²)` of the sampling technique with density `p`.
#[inline]
pub fn power_heuristic(p: f64, q: f64) -> f64 {
    let (p2, q2) = (p * p, q * q);
    if p2 + q2 > 0.0 { p2 / (p2 + q2) } else { 0.0 }
}
