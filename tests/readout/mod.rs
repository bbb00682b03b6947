//! Tests of the readouts at points (`ugo::readout`): the luminance meter and the
//! cylindrical and semi-cylindrical illuminance against closed forms (issue 17, item 7);
//! the UGR at observers against a calculation by hand (issue 38).

mod correction;
mod cylindrical;
mod error_bar;
mod glare_grid;
mod glossy;
mod grid_ugr;
mod meter;
mod ugr;
mod ugr_table;

use crate::support::{build, solve};
use std::path::Path;
use ugo::model::Model;
use ugo::progress::Silent;
use ugo::readout::field::Field;
use ugo::readout::probe::{ProbeReading, read_probes};
use ugo::scene::Scene;

/// The probes of the case `text`, read from its solved field.
fn readings(text: &str) -> Vec<ProbeReading> {
    let scene = Scene::parse(Path::new("cases/test.toml"), text.to_string()).unwrap_or_else(|e| panic!("{e}"));
    let (model, field) = solved(&scene);
    read_probes(&scene.probes, &model, &field, &Silent)
}

/// The model of `scene` and its solved field.
fn solved(scene: &Scene) -> (Model, Field) {
    let model = build(scene);
    // A black room lit only by luminaires has L0 = 0, and so is its field.
    let black = model.l0.iter().all(|&l| l == 0.0);
    let x = if black { vec![0.0; model.l0.len()] } else { solve(&model) };
    let field = Field::from_unknowns(&x, model.kernel.cells());
    (model, field)
}

/// A closed box `[0, side]³` seen from inside, of reflectance `rho`, each face emitting
/// `luminance` (0: none), uniform patches of 0.5 m (named: at that size the size rule would
/// take the hierarchy, which is exact here only to its solve's tolerance).
fn room(side: f64, rho: f64, luminance: f64) -> String {
    let emission = if luminance > 0.0 { format!("emission = {{ luminance = {luminance} }}\n") } else { String::new() };
    format!(
        "[discretization]\npatch_size = 0.5\nkernel = \"uniform\"\n[[material]]\nname = \"grey\"\ntype = \"lambert\"\nreflectance = {rho}\n\
         [[surface]]\nname = \"room\"\nshape = \"box\"\nmaterial = \"grey\"\nmin = [0, 0, 0]\nmax = [{side}, {side}, {side}]\n\
         inside = true\n{emission}"
    )
}
