//! The glazing maintenance factor (`[[window]] maintenance_factor`, `docs/daylight.md`):
//! as in BRE's and CIBSE's average daylight factor `T A θ M / (A (1 − R²))`, `M` multiplies
//! everything that comes in through the window, so SC, ERC, IRC and DF all scale by exactly
//! `M` while `E_h`, the unobstructed sky outside, does not. `[lighting] maintenance_factor`
//! is the electric light's and leaves the daylight alone.

use crate::cie171::solve_model;
use std::path::Path;
use ugo::model::Model;
use ugo::progress::Silent;
use ugo::readout::daylight::{DaylightReadings, read_daylight};
use ugo::readout::field::Field;
use ugo::readout::grid::read_grids;
use ugo::readout::probe::read_probes;
use ugo::scene::Scene;

const WINDOW: &str = "edge_v = [0.0, 1.5, 0.0]\n";

fn office(edits: &[(&str, &str)]) -> Result<Scene, String> {
    let path = Path::new("cases/daylit-office.toml");
    let mut text = std::fs::read_to_string(path).unwrap().replace("patch_size = 0.25", "patch_size = 1.0");
    for (from, to) in edits {
        assert!(text.contains(from), "{from}");
        text = text.replace(from, to);
    }
    Scene::parse(path, text).map_err(|e| e.to_string())
}

fn daylight(scene: &Scene) -> DaylightReadings {
    let model = Model::build(scene, &ugo::progress::Silent).expect("fits");
    let x = solve_model(&model, scene.solver.method);
    let field = Field::from_unknowns(&x, model.kernel.cells());
    let probes = read_probes(&scene.probes, &model, &field, &Silent);
    let grids = read_grids(&scene.grids, &model, &field, &Silent);
    read_daylight(&model, scene.sky.as_ref().unwrap(), &probes, &grids)
}

/// Every probe's SC, ERC, IRC and DF and every grid point's DF of `a` is `factor` times `b`'s.
fn scaled(a: &DaylightReadings, b: &DaylightReadings, factor: f64) {
    assert_eq!(a.horizontal_illuminance, b.horizontal_illuminance, "E_h is the sky outside");
    for (x, y) in a.probes.iter().zip(&b.probes) {
        let pairs = [
            (x.sky_component, y.sky_component),
            (x.externally_reflected, y.externally_reflected),
            (x.internally_reflected, y.internally_reflected),
            (x.daylight_factor, y.daylight_factor),
        ];
        for (u, v) in pairs {
            assert!((u - factor * v).abs() <= 1e-9 * v.abs(), "{u} against {factor} × {v}");
        }
    }
    let df = |d: &DaylightReadings| d.grids.iter().flatten().map(|x| x.daylight_factor).collect::<Vec<f64>>();
    for (u, v) in df(a).into_iter().zip(df(b)) {
        assert!((u - factor * v).abs() <= 1e-9 * v.abs(), "{u} against {factor} × {v}");
    }
}

#[test]
fn the_daylight_factor_scales_by_the_glazing_maintenance_factor_and_not_by_the_electric_one() {
    let clean = daylight(&office(&[]).unwrap());
    let dirty = daylight(&office(&[(WINDOW, "edge_v = [0.0, 1.5, 0.0]\nmaintenance_factor = 0.8\n")]).unwrap());
    eprintln!(
        "front DF {:.4} % clean, {:.4} % with M = 0.8",
        clean.probes[0].daylight_factor, dirty.probes[0].daylight_factor
    );
    scaled(&dirty, &clean, 0.8);
    let electric = office(&[("[sky]", "[lighting]\nmaintenance_factor = 0.5\n\n[sky]")]).unwrap();
    scaled(&daylight(&electric), &clean, 1.0);
}

#[test]
fn a_maintenance_factor_outside_zero_to_one_is_refused_naming_the_window() {
    for bad in ["1.2", "0.0", "-0.5"] {
        let line = format!("edge_v = [0.0, 1.5, 0.0]\nmaintenance_factor = {bad}\n");
        let error = office(&[(WINDOW, &line)]).unwrap_err();
        assert!(error.contains("window") && error.contains("maintenance_factor"), "{error}");
    }
}
