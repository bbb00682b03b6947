//! The error bar of a reading (`docs/design.md` (5.5), `readout/error_bar.rs`) where the
//! error is known exactly: in a white furnace (every face of a closed box of reflectance ρ
//! emitting `L_e`, so `L = L_e/(1 − ρ)` everywhere) the solved field has no error and its
//! bar vanishes; the field of the emission alone (`L_h = L_e`, the first term of the
//! Neumann series) reads `E = π L_e` against the exact `π L_e/(1 − ρ)`, and the bar is that
//! difference: the residual's illuminance `π ρ L_e` times the gain `1/(1 − ρ)`. So for every
//! kind of probe (the cylindrical kinds pool their planes' directions), every grid point
//! (pooled with its neighbours, `readout/grid_error.rs`) and a grid's `E_avg` and `E_min`
//! ((5.6)), which all read `π L_e` there. The tolerance is the probes' 1e-4: every sample
//! is the same `π ρ L_e` up to the gather's exact factors summing to 1 in the closed box,
//! so pooling adds nothing to it.

use super::room;
use crate::support::{build, solve};
use glam::DVec3;
use std::f64::consts::PI;
use std::path::Path;
use std::sync::atomic::{AtomicU64, Ordering};
use ugo::progress::{Progress, Silent};
use ugo::readout::error_bar::{estimate_errors, samples};
use ugo::readout::field::Field;
use ugo::readout::grid::{read_grids, read_grids_cut_by, read_grids_each};
use ugo::readout::grid_error::grid_errors;
use ugo::readout::lit::Lit;
use ugo::readout::probe::{ProbeReading, read_probes};
use ugo::scene::Scene;

const PROBES: &str = "[[probe]]\nname = \"centre\"\nposition = [0.5, 0.5, 0.5]\nnormal = [0, 1, 0]\n\
                      [[probe]]\nname = \"by the edge\"\nposition = [0.3, 0.001, 0.01]\nnormal = [0, 1, 0]\n\
                      [[probe]]\nname = \"cylinder\"\nkind = \"cylindrical\"\nposition = [0.4, 0.5, 0.6]\naxis = [0, 1, 0]\n\
                      [[probe]]\nname = \"half cylinder\"\nkind = \"semi_cylindrical\"\nposition = [0.6, 0.3, 0.4]\n\
                      direction = [1, 0, 0]\naxis = [0, 1, 0]\n";

/// A grid across the middle of the furnace and one on its floor, up to its edges.
const GRIDS: &str = "[[grid]]\nname = \"middle\"\norigin = [0.1, 0.5, 0.1]\nedge_u = [0.8, 0, 0]\nedge_v = [0, 0, 0.8]\n\
                     resolution = [4, 3]\nnormal = [0, 1, 0]\n\
                     [[grid]]\nname = \"floor\"\norigin = [0, 0, 0]\nedge_u = [1, 0, 0]\nedge_v = [0, 0, 1]\n\
                     resolution = [5, 5]\nnormal = [0, 1, 0]\n";

/// The furnace's probes read from its solved field (`solved`) or from its emission alone,
/// with their error bars.
fn furnace(rho: f64, emission: f64, solved: bool) -> Vec<ProbeReading> {
    let text = format!("{}{PROBES}{GRIDS}", room(1.0, rho, emission));
    let scene = Scene::parse(Path::new("cases/test.toml"), text).unwrap_or_else(|e| panic!("{e}"));
    let model = build(&scene);
    let x = if solved { solve(&model) } else { model.l0.clone() };
    let field = Field::from_unknowns(&x, model.kernel.cells());
    let mut readings = read_probes(&scene.probes, &model, &field, &Silent);
    estimate_errors(&mut readings, &model, &field, &Silent);
    readings
}

#[test]
fn a_solved_furnace_has_no_error_bar() {
    let exact = PI * 10.0 / (1.0 - 0.8);
    for r in furnace(0.8, 10.0, true) {
        let bar = r.error.expect("a probe has a bar");
        eprintln!("{}: E {:.6} lx (exact {exact:.6}), bar {bar:.3e} lx", r.name, r.illuminance);
        assert!(bar < 1e-6 * exact, "{}: a bar of {bar:.3e} lx on an exact field", r.name);
    }
}

#[test]
fn the_error_bar_of_the_emission_alone_is_its_error() {
    let exact = PI * 10.0 / (1.0 - 0.5);
    for r in furnace(0.5, 10.0, false) {
        let (error, bar) = ((r.illuminance - exact).abs(), r.error.expect("a probe has a bar"));
        eprintln!("{}: E {:.6} lx (exact {exact:.6}), error {error:.6} lx, bar {bar:.6} lx", r.name, r.illuminance);
        assert!((bar / error - 1.0).abs() < 1e-4, "{}: a bar of {bar} lx for an error of {error} lx", r.name);
    }
}

/// Each grid of the furnace with every point's `(E, δE)`, and `(E_avg, δE_avg)` and
/// `(E_min, δE_min)`, read from its solved field (`solved`) or from its emission alone.
#[allow(clippy::type_complexity)]
fn furnace_grids(rho: f64, solved: bool) -> Vec<(String, Vec<(f64, f64)>, (f64, f64), (f64, f64))> {
    let text = format!("{}{GRIDS}", room(1.0, rho, 10.0));
    let scene = Scene::parse(Path::new("cases/test.toml"), text).unwrap_or_else(|e| panic!("{e}"));
    let model = build(&scene);
    let x = if solved { solve(&model) } else { model.l0.clone() };
    let field = Field::from_unknowns(&x, model.kernel.cells());
    let grids = read_grids(&scene.grids, &model, &field, &Silent);
    let bars = grid_errors(&grids, &model, &field, &Silent);
    grids
        .iter()
        .zip(&bars)
        .map(|(g, b)| {
            assert_eq!(g.left_out(), 0, "{}: every point counts", g.grid.name);
            let st = g.stats();
            let points = g.illuminance.iter().copied().zip(b.points.iter().copied()).collect();
            (g.grid.name.clone(), points, (st.average, b.average), (st.min, b.min))
        })
        .collect()
}

#[test]
fn a_solved_furnace_has_no_error_bar_on_its_grids() {
    let exact = PI * 10.0 / (1.0 - 0.8);
    for (name, points, average, min) in furnace_grids(0.8, true) {
        let largest = points.iter().map(|p| p.1).fold(0.0, f64::max);
        eprintln!(
            "{name}: largest bar {largest:.3e} lx, E_avg ± {:.3e}, E_min ± {:.3e} (exact {exact:.6})",
            average.1, min.1
        );
        assert!(largest.max(average.1).max(min.1) < 1e-6 * exact, "{name}: bars on an exact field");
    }
}

#[test]
fn the_error_bars_of_a_grid_on_the_emission_alone_are_its_errors() {
    let exact = PI * 10.0 / (1.0 - 0.5);
    let close = |bar: f64, error: f64| (bar / error - 1.0).abs() < 1e-4;
    for (name, points, average, min) in furnace_grids(0.5, false) {
        for (i, &(e, bar)) in points.iter().enumerate() {
            let error = (e - exact).abs();
            assert!(close(bar, error), "{name}, point {i}: a bar of {bar} lx for an error of {error} lx");
        }
        let (avg_error, min_error) = ((average.0 - exact).abs(), (min.0 - exact).abs());
        eprintln!(
            "{name}: E_avg {:.6} ± {:.6} (error {avg_error:.6}), E_min {:.6} ± {:.6} (error {min_error:.6})",
            average.0, average.1, min.0, min.1
        );
        assert!(close(average.1, avg_error), "{name}: E_avg ± {} for an error of {avg_error}", average.1);
        assert!(close(min.1, min_error), "{name}: E_min ± {} for an error of {min_error}", min.1);
    }
}

/// Records what a stage announces and how far it advances.
#[derive(Default)]
struct Counted {
    total: AtomicU64,
    done: AtomicU64,
}

impl Progress for Counted {
    fn begin(&self, _: &str, total: u64) {
        self.total.store(total, Ordering::Relaxed);
    }
    fn advance(&self, done: u64) {
        self.done.fetch_add(done, Ordering::Relaxed);
    }
    fn at(&self, _: u64, _: &str) {}
    fn end(&self) {}
}

#[test]
fn the_grids_error_bars_tell_their_progress_point_by_point() {
    let text = format!("{}{GRIDS}", room(1.0, 0.5, 10.0));
    let scene = Scene::parse(Path::new("cases/test.toml"), text).unwrap_or_else(|e| panic!("{e}"));
    let model = build(&scene);
    let field = Field::from_unknowns(&model.l0, model.kernel.cells());
    let grids = read_grids(&scene.grids, &model, &field, &Silent);
    let progress = Counted::default();
    grid_errors(&grids, &model, &field, &progress);
    let points: usize = grids.iter().map(|g| g.points.len() - g.left_out()).sum();
    assert!(grids.len() > 1 && points > grids.len(), "{points} points in {} grids", grids.len());
    assert_eq!(progress.total.load(Ordering::Relaxed), points as u64, "announced");
    assert_eq!(progress.done.load(Ordering::Relaxed), points as u64, "advanced");
}

/// Two fields gathered at once (`readout/lit.rs`: one landing and one gather a direction,
/// each piece weighed by both) give each the samples and grid readings it gets alone, to
/// round-off; and a
/// field under light other than the model's own is refused where a gather would read the
/// model's own sources (a glossy surface).
#[test]
fn fields_gathered_at_once_sample_as_each_alone() {
    let text = format!("{}{PROBES}{GRIDS}", room(1.0, 0.6, 10.0));
    let scene = Scene::parse(Path::new("cases/test.toml"), text).unwrap_or_else(|e| panic!("{e}"));
    let model = build(&scene);
    let cells = model.kernel.cells();
    let (solved, emitted) = (Field::from_unknowns(&solve(&model), cells), Field::from_unknowns(&model.l0, cells));
    let receivers = [(DVec3::new(0.5, 0.5, 0.5), DVec3::Y), (DVec3::new(0.3, 0.001, 0.01), DVec3::Y)];
    let by = [&solved, &emitted];
    let lits = [Lit::own(&model, &solved), Lit::own(&model, &emitted)];
    let together = samples(&model, &lits, &receivers, 16, &by, &Silent);
    for (lit, together) in lits.iter().zip(&together) {
        let alone = samples(&model, std::slice::from_ref(lit), &receivers, 16, &by, &Silent).swap_remove(0);
        assert_eq!(alone.len(), together.len());
        for (a, t) in alone.iter().zip(together) {
            assert!((a.illuminance - t.illuminance).abs() <= 1e-12 * a.illuminance.abs().max(1.0), "{a:?} {t:?}");
            assert_eq!(a.albedo, t.albedo);
        }
    }
    assert!(together[0].iter().zip(&together[1]).any(|(a, b)| a.illuminance != b.illuminance), "two fields");
    let grids = read_grids_each(&scene.grids, &model, &lits, &by, &Silent);
    for (field, together) in [&solved, &emitted].into_iter().zip(&grids) {
        let alone = read_grids_cut_by(&scene.grids, &model, field, &by, &Silent);
        for (a, t) in alone.iter().zip(together) {
            let close = |x: &[f64], y: &[f64]| x.iter().zip(y).all(|(x, y)| (x - y).abs() <= 1e-12 * x.abs().max(1.0));
            assert!(close(&a.illuminance, &t.illuminance) && close(&a.direct, &t.direct), "{}", a.grid.name);
        }
    }
    assert!(Lit::apart(&model, &solved, &model.sources, &model.mesh.emission).is_some(), "a Lambertian room");
    let glossy = text_with_phong(&room(1.0, 0.6, 10.0));
    let scene = Scene::parse(Path::new("cases/test.toml"), glossy).unwrap_or_else(|e| panic!("{e}"));
    let model = build(&scene);
    let field = Field::from_unknowns(&model.l0, model.kernel.cells());
    assert!(Lit::apart(&model, &field, &model.sources, &model.mesh.emission).is_none(), "a glossy room");
}

/// `room` with its material made Phong.
fn text_with_phong(room: &str) -> String {
    room.replace(
        "type = \"lambert\"\nreflectance = 0.6",
        "type = \"phong\"\nexponent = 20\nspecular = 0.2\nreflectance = 0.4",
    )
}
