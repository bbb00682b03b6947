//! The error bar of a reading (`docs/design.md` (5.5), `readout/error_bar.rs`) where the
//! error is known exactly: in a white furnace (every face of a closed box of reflectance ρ
//! emitting `L_e`, so `L = L_e/(1 − ρ)` everywhere) the solved field has no error and its
//! bar vanishes; the field of the emission alone (`L_h = L_e`, the first term of the
//! Neumann series) reads `E = π L_e` against the exact `π L_e/(1 − ρ)`, and the bar is that
//! difference: the residual's illuminance `π ρ L_e` times the gain `1/(1 − ρ)`.

use super::room;
use crate::support::{build, solve};
use std::f64::consts::PI;
use std::path::Path;
use ugo::progress::Silent;
use ugo::readout::error_bar::estimate_errors;
use ugo::readout::field::Field;
use ugo::readout::probe::{ProbeReading, read_probes};
use ugo::scene::Scene;

const PROBES: &str = "[[probe]]\nname = \"centre\"\nposition = [0.5, 0.5, 0.5]\nnormal = [0, 1, 0]\n\
                      [[probe]]\nname = \"by the edge\"\nposition = [0.3, 0.001, 0.01]\nnormal = [0, 1, 0]\n";

/// The furnace's probes read from its solved field (`solved`) or from its emission alone,
/// with their error bars.
fn furnace(rho: f64, emission: f64, solved: bool) -> Vec<ProbeReading> {
    let text = format!("{}{PROBES}", room(1.0, rho, emission));
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
        let bar = r.error.expect("a point sensor has a bar");
        eprintln!("{}: E {:.6} lx (exact {exact:.6}), bar {bar:.3e} lx", r.name, r.illuminance);
        assert!(bar < 1e-6 * exact, "{}: a bar of {bar:.3e} lx on an exact field", r.name);
    }
}

#[test]
fn the_error_bar_of_the_emission_alone_is_its_error() {
    let exact = PI * 10.0 / (1.0 - 0.5);
    for r in furnace(0.5, 10.0, false) {
        let (error, bar) = ((r.illuminance - exact).abs(), r.error.expect("a point sensor has a bar"));
        eprintln!("{}: E {:.6} lx (exact {exact:.6}), error {error:.6} lx, bar {bar:.6} lx", r.name, r.illuminance);
        assert!((bar / error - 1.0).abs() < 1e-4, "{}: a bar of {bar} lx for an error of {error} lx", r.name);
    }
}
