//! The CIE 171:2006 analytic test cases (`cases/cie171/`) against their published
//! reference values. CIE gives no tolerance and validators commonly accept 5 % per point;
//! every point here must agree within 1 %. Each test prints its rows as they appear in
//! `docs/validation.md`: case, point, reference, ugo, difference
//! (`cargo test --release cie171 -- --nocapture`).

mod area_source;
mod cube;
mod daylight;
mod flux;
mod obstruction;
mod point_source;
mod reflection;

use std::path::Path;
use ugo::kernel::{Explicit, Factored};
use ugo::model::Model;
use ugo::progress::Silent;
use ugo::readout::field::Field;
use ugo::readout::probe::{ProbeReading, read_probes};
use ugo::scene::{Hierarchical, KernelKind, Scene};
use ugo::solve::{Method, SolveParams, System, solve};

/// Agreement asked of every analytic point.
pub const TOLERANCE: f64 = 0.01;

/// A case solved with its own method, and its probes read.
pub struct Solved {
    pub scene: Scene,
    pub model: Model,
    pub x: Vec<f64>,
    pub probes: Vec<ProbeReading>,
}

/// Loads `cases/cie171/<name>.toml` and solves it.
pub fn solved(name: &str) -> Solved {
    solved_with(name, |_| ())
}

/// [`solved`] through the hierarchy a case without `kernel` would get at its patch size
/// above the size rule's threshold (issue 14.4).
pub fn solved_hierarchically(name: &str) -> Solved {
    solved_with(name, |scene| {
        scene.discretization.kernel = KernelKind::Hierarchical(Hierarchical::over(scene.discretization.patch_size));
    })
}

/// Loads `cases/cie171/<name>.toml`, lets `change` alter it, and solves it.
fn solved_with(name: &str, change: impl Fn(&mut Scene)) -> Solved {
    let mut scene =
        Scene::load(&Path::new("cases/cie171").join(format!("{name}.toml"))).unwrap_or_else(|e| panic!("{e}"));
    change(&mut scene);
    let model = Model::build(&scene, &ugo::progress::Silent).expect("fits in memory");
    let x = solve_model(&model, scene.solver.method);
    let probes = read_probes(&scene.probes, &model, &Field::from_unknowns(&x, model.kernel.cells()), &Silent);
    Solved { scene, model, x, probes }
}

/// `x = L0 + K x` for the model's current source and blocks.
pub fn solve_model(model: &Model, method: Method) -> Vec<f64> {
    let limit = 1 << 30;
    let explicit = method.needs_explicit().then(|| Explicit(model.kernel.explicit(limit).expect("fits")));
    let areas: Vec<f64> = model.mesh.patches.iter().map(|p| p.area).collect();
    let factored = Factored::new(&model.kernel);
    let system = System::of(&model.kernel, &factored, explicit.as_ref(), &areas, &model.l0);
    let params =
        SolveParams { tolerance: 1e-10, max_iterations: 10_000, memory_limit: limit, ..SolveParams::default() };
    solve(method, &system, &params, &mut |_, _| {}).expect("converges").0
}

impl Solved {
    /// The probe named `name`.
    pub fn probe(&self, name: &str) -> &ProbeReading {
        self.probes.iter().find(|p| p.name == name).unwrap_or_else(|| panic!("no probe {name}"))
    }
}

/// Prints `(point, reference, ugo)` rows as a markdown table and checks each within
/// [`TOLERANCE`] (a reference of 0 must come out below 0.005 in its own unit).
pub fn compare(case: &str, rows: &[(&str, f64, f64)]) {
    let mut worst: f64 = 0.0;
    for &(point, reference, ugo) in rows {
        let (shown, off) = if reference == 0.0 {
            (format!("{ugo:+.4} (absolute)"), ugo.abs() >= 0.005)
        } else {
            let difference = ugo / reference - 1.0;
            worst = worst.max(difference.abs());
            (format!("{:+.2} %", 100.0 * difference), difference.abs() > TOLERANCE)
        };
        eprintln!("| {case} | {point} | {reference} | {ugo:.4} | {shown} |");
        assert!(!off, "CIE 171 {case}, point {point}: reference {reference}, ugo {ugo}");
    }
    eprintln!("| {case} | worst | | | {:.2} % |", 100.0 * worst);
}
