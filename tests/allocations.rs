//! The hot loops allocate nothing once warm: the kernel's applications (factored,
//! explicit, reduced to a basis, hierarchical with its transpose) and the visibility queries. This is its own test binary
//! (its own process) because it counts every heap allocation through the global
//! allocator; one test, so nothing else runs beside it. rayon's work-stealing deques
//! grow and shrink now and then (a handful of allocations per many applications, none
//! per row or per non-zero), so a parallel application is allowed less than one
//! allocation on average; a loop that allocated per row would make thousands.

use glam::DVec3;
use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicUsize, Ordering};
use ugo::basis::{Basis, Factorization, Reduced};
use ugo::directions::Scheme;
use ugo::kernel::{Explicit, Factored, Transport};
use ugo::model::Model;
use ugo::scene::{Hierarchical, KernelKind, Scene};
use ugo::solve::LinOp;
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
/// One pool for the whole test: the teardown of a dropped pool's threads allocates too.
fn allocations(pool: &rayon::ThreadPool, work: impl FnMut() + Send) -> usize {
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
    let mut scene = Scene::load(std::path::Path::new("cases/glossy-cornell.toml")).unwrap();
    (scene.discretization.patch_size, scene.discretization.directions) = (0.15, Scheme::Cells(16));
    let model = Model::build(&scene, &ugo::progress::Silent).unwrap();
    let pool = rayon::ThreadPoolBuilder::new().num_threads(2).build().unwrap();
    let n = model.l0.len();
    let x: Vec<f64> = (0..n).map(|i| 1.0 + (i % 7) as f64).collect();
    let mut y = vec![0.0; n];

    let factored = Factored::new(&model.kernel);
    let rows = n as f64;
    let few = |count: usize, what: &str| {
        assert!(count < 20, "{what}: {count} allocations in 20 applications over {rows} rows")
    };
    few(allocations(&pool, || factored.apply(&x, &mut y)), "factored K x");
    let explicit = Explicit(model.kernel.explicit(u64::MAX).unwrap());
    few(allocations(&pool, || explicit.apply(&x, &mut y)), "explicit K x");
    let factors = Factorization::new(Basis::Sh { lmax: 2 }, &model.kernel.blocks, &model.kernel.directions).unwrap();
    let reduced = Reduced::new(&model.kernel, &factors);
    let c = vec![0.5; reduced.dim()];
    let mut z = vec![0.0; reduced.dim()];
    few(allocations(&pool, || reduced.apply(&c, &mut z)), "reduced Φᵀ G Ψ c");

    scene.discretization.patch_size = 0.05;
    scene.discretization.kernel = KernelKind::Hierarchical(Hierarchical {
        root_size: 0.25,
        link_tolerance: 1e-2,
        passes: ugo::scene::Hierarchical::DEFAULT_PASSES,
    });
    let tree = Model::build(&scene, &ugo::progress::Silent).unwrap();
    let Transport::Hierarchical(op) = &tree.kernel.g else { panic!("not hierarchical") };
    let hierarchical = Factored::new(&tree.kernel);
    let m = op.dim();
    let (u, mut w) = ((0..m).map(|i| 1.0 + (i % 5) as f64).collect::<Vec<f64>>(), vec![0.0; m]);
    few(allocations(&pool, || hierarchical.apply(&u, &mut w)), "hierarchical K x");
    few(allocations(&pool, || op.leaving(&u, &mut w)), "hierarchical Gᵀ y");

    let v = &model.visibility;
    let (a, b) = (model.mesh.patches[0].centroid, model.mesh.patches[model.mesh.len() / 2].centroid);
    let faces = [model.mesh.patches[0].face, model.mesh.patches[model.mesh.len() / 2].face];
    let mut seen = 0;
    few(allocations(&pool, || seen += v.visible(a, b, faces) as usize), "occlusion query");
    let mut hits = 0;
    let up = DVec3::new(0.3, 1.0, 0.2);
    few(
        allocations(&pool, || hits += v.closest_hit(DVec3::new(0.28, 0.2, 0.28), up, NO_FACE).is_some() as usize),
        "closest hit",
    );
    assert!(hits > 0);
}
