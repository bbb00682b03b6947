//! The hierarchical kernel (`docs/design.md` §3b) against the uniform kernel on the same leaves,
//! closed forms, and its own invariants (coverage of leaf pairs, growth of links).

mod bundles;
mod closure;
mod clusters;
mod coverage;
mod edges;
mod explicit;
mod growth;
mod importance;
mod memory;
mod model;
mod monte_carlo;
mod norms;
mod open_box;
mod overhang;
mod partition;
mod plates;
mod progress;
mod push;
mod rebalance;
mod rooms_apart;
mod slots;
mod spectrum;
mod transpose;
mod window_splits;

use glam::DVec3;
use ugo::directions::DirectionSet;
use ugo::geometry::Mesh;
use ugo::geometry::{Emission, Shape};
use ugo::kernel::hierarchy::{Hierarchy, Options};
use ugo::kernel::{Factored, Kernel, Refined, refine_with_solves};
use ugo::progress::Silent;
use ugo::scene::Scene;
use ugo::solve::{Method, SolveError, SolveParams, System, solve};
use ugo::transfer::exposure::measure_exposure;
use ugo::visibility::Visibility;

use crate::support::{furnace, lambert, surface};

/// The smallest element size of the slots' and edges' rooms, m.
pub const PATCH_SIZE: f64 = 0.12;

/// The hierarchy (roots of 1 m, links to 1e-2, leaves down to [`PATCH_SIZE`]) of a closed
/// 2 m room holding a box from `min` to `max`, m.
pub fn room_with(name: &str, min: DVec3, max: DVec3) -> Hierarchy {
    let mut room = furnace(2.0, 0.5, 1.0, 10.0);
    room.surfaces.push(surface(name, Shape::Box { min, max, rotate_y_deg: 0.0 }, 0, false, None));
    hierarchy(&room, 1.0, DirectionSet::single(), options(1e-2, PATCH_SIZE))
}

/// The longest edge of a leaf, m.
pub fn longest_edge(p: &ugo::geometry::Patch) -> f64 {
    ugo::kernel::hierarchy::longest_edge(&p.polygon)
}

/// The hierarchy of `scene` over roots meshed at `root_size` (m).
pub fn hierarchy(scene: &Scene, root_size: f64, directions: DirectionSet, options: Options) -> Hierarchy {
    let (roots, visibility) = measured_roots(scene, root_size);
    let blocks = scene.materials.iter().map(|m| m.model.block(&directions)).collect();
    let k = directions.len();
    let l0: Vec<f64> = roots.emission.iter().flat_map(|&e| std::iter::repeat_n(e, k)).collect();
    Hierarchy::new(&roots, visibility, directions, blocks, options, &l0, &Silent).expect("the linking fits in memory")
}

/// The roots of `scene` meshed at `root_size` (m) with their exposed areas, and their ray
/// caster, as `Hierarchy::new` takes them.
pub fn measured_roots(scene: &Scene, root_size: f64) -> (Mesh, Visibility) {
    let mut roots = Mesh::build(&scene.surfaces, root_size);
    let visibility = Visibility::build(&roots);
    measure_exposure(&mut roots, &visibility, &Silent);
    (roots, visibility)
}

/// Options with `tolerance` and `patch_size` (m, the finest leaves), the rest default.
pub fn options(tolerance: f64, patch_size: f64) -> Options {
    Options { tolerance, patch_size, ..Options::default() }
}

/// `x = b + K x` by `method` to a relative residual of `1e-10` (relaxed by `scale`).
pub fn solver(method: Method) -> impl FnMut(&Kernel, &[f64], f64) -> Result<Vec<f64>, SolveError> {
    move |kernel, b, scale| {
        let params = SolveParams { tolerance: 1e-10 * scale, max_iterations: 10_000, ..SolveParams::default() };
        let operator = Factored::new(kernel);
        let system = System { operator: &operator, explicit: None, areas: &[], l0: b };
        solve(method, &system, &params, &mut |_, _| {}).map(|(x, _)| x)
    }
}

/// Solves and refines in passes with `method`: the field and the kernel on the final leaves.
pub fn solved(h: &mut Hierarchy, method: Method) -> (Vec<f64>, Kernel) {
    type Failure = Box<dyn std::error::Error + Send + Sync>;
    let mut solve = solver(method);
    let Refined { x, kernel, history, .. } = refine_with_solves(
        h,
        &mut |h| Ok::<_, Failure>(h.emission()),
        &mut |k: &Kernel, b: &[f64], s: f64| solve(k, b, s).map_err(Failure::from),
        &mut |_: &Hierarchy, _: &[f64]| Ok(None),
        &Silent,
    )
    .expect("the solve converges");
    eprintln!("passes: {history:?}");
    (x, kernel)
}

/// The kernel `K = B·G` on the current leaves of `h`.
pub fn kernel(h: &mut Hierarchy) -> Kernel {
    Kernel::on_leaves(h, &Silent).0
}

/// Links of the hierarchical kernel `k`.
pub fn links(k: &Kernel) -> usize {
    k.g.hierarchy().map_or(0, |g| g.links())
}

/// A closed unit cube seen from inside (reflectance `rho`, every face emitting 1 cd/m²)
/// with a floating block of reflectance 0.7 inside it that casts shadows.
pub fn box_with_block(rho: f64) -> Scene {
    let mut s = furnace(1.0, rho, 1.0, 1.0);
    s.materials.push(lambert("block", 0.7));
    let block = Shape::Box { min: DVec3::new(0.35, 0.2, 0.35), max: DVec3::new(0.65, 0.5, 0.65), rotate_y_deg: 20.0 };
    s.surfaces.push(surface("block", block, 1, false, None::<Emission>));
    s
}

/// Largest `|a − b|` relative to the largest `|b|`.
pub fn relative_difference(a: &[f64], b: &[f64]) -> f64 {
    let scale = b.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    a.iter().zip(b).fold(0.0f64, |m, (x, y)| m.max((x - y).abs())) / scale
}
