//! `ugo bench`: the throughput of every stage next to the machine's limit, as a table
//! and as JSON (issue 9, `docs/performance.md`): occlusion rays per second (all BVH
//! layouts with `--layouts`), form-factor pairs per second during assembly and its
//! speed-up from one thread to all, the sparse product in GB/s of matrix traffic against
//! a STREAM-like triad measured in the same run, the time per application of the
//! factored operator, and assemble-and-solve time and peak memory over several patch
//! sizes with the fitted growth exponent. `--export DIR` writes the same rays and matrix
//! for the peers (Embree, scipy). With `--kernel hierarchical` it measures the rays, the
//! operator's application and the hierarchy's curve over leaf sizes (`--patch-size`) instead:
//! leaves, links, rays and time against N with their fitted exponents (`hierarchy.rs`;
//! the uniform kernel's run in `uniform.rs`). The measuring is `ugo::study::bench`'s; here
//! the flags are read and the figures printed.

mod hierarchy;
mod json;
mod layouts;
mod options;
mod scaling;
mod uniform;

pub use options::BenchOptions;

use super::load;
use anyhow::Result;
use ugo::model::Model;
use ugo::scene::KernelKind;
use ugo::study::bench;

/// Loads the case with the flags' discretization, refuses one over the memory limit before
/// meshing, and runs the kernel's bench.
pub fn run(o: &BenchOptions) -> Result<()> {
    for &n in &o.lu {
        layouts::print_dense_lu(&bench::dense_lu(n));
    }
    let scene = load(&o.case, &o.discretize)?;
    // Refused before meshing, from the surfaces, like `solve` (`kernel::forecast`).
    Model::forecast(&scene).check(scene.discretization.memory_limit)?;
    if let Some(json) = &o.json {
        super::check_writable(json)?;
    }
    if let KernelKind::Hierarchical(h) = scene.discretization.kernel {
        return hierarchy::run(o, &scene, h);
    }
    uniform::run(o, &scene)
}
