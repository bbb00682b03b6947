//! The hot loops allocate nothing once warm: the kernel's applications (factored,
//! explicit, reduced to a basis) and the visibility queries. This is its own test binary
//! (its own process) because it counts every heap allocation through the global
//! allocator; one test, so nothing else runs beside it.

use glam::DVec3;
use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicUsize, Ordering};
use ugo::basis::{Basis, Factorization, Reduced};
use ugo::directions::DirectionSet;
use ugo::kernel::{Explicit, Factored, LinOp};
use ugo::model::{Model, ModelOptions};
use ugo::scene::Scene;
use ugo::visibility::NO_FACE;

struct Counting;

static ALLOCATIONS: AtomicUsize = AtomicUsize::new(0);

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        ALLOCATIONS.fetch_add(1, Ordering::Relaxed);
        unsafe { System.alloc(layout) }
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) }
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, size: usize) -> *mut u8 {
        ALLOCATIONS.fetch_add(1, Ordering::Relaxed);
        unsafe { System.realloc(ptr, layout, size) }
    }
}

#[global_allocator]
static COUNTING: Counting = Counting;

/// Allocations made by `work` run 20 times after 3 warm-up runs, inside a rayon pool (a
/// parallel loop started from outside a pool goes through rayon's injector queue, which
/// allocates a block every 63 jobs: rayon's bookkeeping, not ours).
fn allocations(work: impl FnMut() + Send) -> usize {
    let pool = rayon::ThreadPoolBuilder::new().num_threads(2).build().unwrap();
    let mut work = work;
    pool.install(move || {
        for _ in 0..3 {
            work();
        }
        let before = ALLOCATIONS.load(Ordering::SeqCst);
        for _ in 0..20 {
            work();
        }
        ALLOCATIONS.load(Ordering::SeqCst) - before
    })
}

#[test]
fn kernel_applications_and_ray_queries_do_not_allocate() {
    let scene = Scene::load(std::path::Path::new("cases/glossy-cornell.toml")).unwrap();
    let options =
        ModelOptions { patch_size: 0.15, directions: DirectionSet::hemisphere(16), ..ModelOptions::of(&scene) };
    let model = Model::build(&scene, &options, &|_| {}, &|_| {}).unwrap();
    let n = model.l0.len();
    let x: Vec<f64> = (0..n).map(|i| 1.0 + (i % 7) as f64).collect();
    let mut y = vec![0.0; n];

    let factored = Factored::new(&model.kernel);
    assert_eq!(allocations(|| factored.apply(&x, &mut y)), 0, "factored K x");
    let explicit = Explicit(model.kernel.explicit(u64::MAX).unwrap());
    assert_eq!(allocations(|| explicit.apply(&x, &mut y)), 0, "explicit K x");
    let factors = Factorization::new(Basis::Sh { lmax: 2 }, &model.kernel.blocks, &model.kernel.directions).unwrap();
    let reduced = Reduced::new(&model.kernel, &factors);
    let c = vec![0.5; reduced.dim()];
    let mut z = vec![0.0; reduced.dim()];
    assert_eq!(allocations(|| reduced.apply(&c, &mut z)), 0, "reduced Φᵀ G Ψ c");

    let v = &model.visibility;
    let (a, b) = (model.mesh.patches[0].centroid, model.mesh.patches[model.mesh.len() / 2].centroid);
    let faces = [model.mesh.patches[0].face, model.mesh.patches[model.mesh.len() / 2].face];
    let mut seen = 0;
    assert_eq!(allocations(|| seen += v.visible(a, b, faces) as usize), 0, "occlusion query");
    let mut hits = 0;
    let up = DVec3::new(0.3, 1.0, 0.2);
    assert_eq!(
        allocations(|| hits += v.closest_hit(DVec3::new(0.28, 0.2, 0.28), up, NO_FACE).is_some() as usize),
        0,
        "closest hit"
    );
    assert!(hits > 0);
}
