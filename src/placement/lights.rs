//! How much of the direct light of the sources in front of a point reaches it: each point
//! luminaire and parallel light with one shadow ray, the emitting surfaces through
//! [`POINTS`] points drawn by flux (stratified over the emitters, as the tracer's next-event
//! estimation draws them), each weighted by the illuminance it would give unshadowed, so
//! that the share is that of the direct illuminance. The sky through `[[window]]` openings
//! is not counted: a daylit room's umbrae are those of its luminaires and emitters only.

use crate::luminaire::{Light, Source};
use crate::random::Rng;
use crate::trace::World;
use crate::visibility::NO_FACE;
use glam::DVec3;

/// Points drawn on the emitting surfaces for one point's share.
pub const POINTS: usize = 64;

/// The direct illuminance at a point, unshadowed and shadowed (estimates, lx).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Lit {
    /// What the sources in front of the point would give it unshadowed.
    pub reaching: f64,
    /// What arrives past the shadows.
    pub arriving: f64,
}

impl Lit {
    /// The share of the direct light that arrives; `None` when no source is in front.
    pub fn share(&self) -> Option<f64> {
        (self.reaching > 0.0).then(|| self.arriving / self.reaching)
    }

    fn add(&mut self, e: f64, seen: bool) {
        if e > 0.0 {
            self.reaching += e;
            self.arriving += if seen { e } else { 0.0 };
        }
    }
}

/// The direct light of `sources` and of `world`'s emitters at `p` on a receiver facing the
/// unit `n` (lying on face `face`, or on none), the emitters' points drawn from `rng`.
pub fn lit(world: &World, sources: &[Source], p: DVec3, n: DVec3, face: u32, rng: &mut Rng) -> Lit {
    let mut lit = Lit::default();
    let visibility = &world.visibility;
    for source in sources {
        match &source.light {
            Light::Point { position, .. } => {
                let r = p - *position;
                let distance2 = r.length_squared();
                let w = r / distance2.sqrt();
                let e = source.intensity(w) * (-w).dot(n) / distance2;
                lit.add(e, e > 0.0 && visibility.visible(*position, p, [NO_FACE, face]));
            }
            Light::Parallel { direction, illuminance, glass } => {
                let e = illuminance * (-*direction).dot(n) * glass.share(p, -*direction);
                lit.add(e, e > 0.0 && visibility.escapes(p, -*direction, face));
            }
            Light::Window { .. } => {}
        }
    }
    for k in 0..POINTS {
        let u = [(k as f64 + rng.uniform()) / POINTS as f64, rng.uniform(), rng.uniform()];
        let Some(light) = world.emitters.sample_towards(&world.mesh, p, u) else { continue };
        let e = light.luminance * n.dot(light.direction) / light.pdf / POINTS as f64;
        lit.add(e, e > 0.0 && visibility.visible(p, light.point, [face, light.face]));
    }
    lit
}
