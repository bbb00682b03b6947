//! The occlusion rays of `ugo bench`: segments like the assembly's, between stratified
//! points of random facing patch pairs, timed through the default BVH.

use super::error::BenchError;
use super::links::LinkRays;
use super::pairs::facing_pairs;
use crate::geometry::Mesh;
use crate::scene::Scene;
use crate::transfer::occlusion::sample_points;
use crate::visibility::Visibility;
use rayon::prelude::*;
use std::time::Instant;

pub use crate::visibility::Segment;

/// The uniform mesh of a case at one patch size, its BVH, the segments and their rate.
pub struct Occlusion {
    /// The mesh.
    pub mesh: Mesh,
    /// Its ray caster, in the default layout.
    pub visibility: Visibility,
    /// Segments between interior points of random facing patch pairs.
    pub segments: Vec<Segment>,
    /// Occlusion rays per second through them (the better of two runs, all threads of the
    /// current pool).
    pub rays_per_second: f64,
    /// The same on one thread: the per-core figure that Embree's single-threaded batch in
    /// `docs/peers/peers.py` is compared with.
    pub one_thread_rays_per_second: f64,
    /// Links' segments traced one by one and together, one thread.
    pub links: LinkRays,
}

impl Occlusion {
    /// Meshes `scene` at `size` and times `count` segments; refused when no facing pair
    /// turns up (a scene of one plate, or of luminaires and a floor only, has nothing to
    /// time).
    pub fn measure(scene: &Scene, size: f64, count: usize) -> Result<Occlusion, BenchError> {
        let mesh = Mesh::build(&scene.surfaces, size);
        let Some(segments) = segments(&mesh, count) else {
            return Err(BenchError::NoFacingPairs { patches: mesh.len() });
        };
        let visibility = Visibility::build(&mesh);
        let rate = || rays_per_second(&visibility, &segments);
        let (all, one) = (rate().max(rate()), rayon::ThreadPoolBuilder::new().num_threads(1).build()?.install(rate));
        let links = LinkRays::measure(&mesh, &visibility, count / 8).expect("the segments' facing pairs");
        Ok(Occlusion { mesh, visibility, segments, rays_per_second: all, one_thread_rays_per_second: one, links })
    }
}

/// Occlusion rays per second through `visibility` (all threads of the current pool).
fn rays_per_second(visibility: &Visibility, segments: &[Segment]) -> f64 {
    let t = Instant::now();
    let seen: usize = segments.par_iter().map(|(a, b, f)| visibility.visible(*a, *b, *f) as usize).sum();
    std::hint::black_box(seen);
    segments.len() as f64 / t.elapsed().as_secs_f64()
}

/// `count` segments between interior points of random facing patch pairs (reproducible),
/// or `None` when no facing pair turns up in `1000 · count` draws.
fn segments(mesh: &Mesh, count: usize) -> Option<Vec<Segment>> {
    facing_pairs(mesh, count, |a, b, rng| {
        let pa = sample_points(a)[(rng.next_u64() % 4) as usize];
        let pb = sample_points(b)[(rng.next_u64() % 4) as usize];
        (pa, pb, [a.face, b.face])
    })
}
