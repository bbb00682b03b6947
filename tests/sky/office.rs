//! The daylit office (`cases/daylit-office.toml`): a vertical opening under the CIE
//! overcast sky. The flux through an unobstructed vertical opening is its area times the
//! vertical illuminance outside, `L_z (π/6 + 4/9)` from the overcast sky plus `π L_g / 2`
//! from the ground, and all of it lands on the closed room's surfaces; the daylight
//! quantities add up, `DF = SC + ERC + IRC`, with the work plane below the sill seeing no
//! ground and the ceiling no sky.

use crate::cie171::solve_model;
use std::f64::consts::PI;
use std::path::Path;
use ugo::model::Model;
use ugo::progress::Silent;
use ugo::readout::daylight::{read_daylight, stats};
use ugo::readout::field::Field;
use ugo::readout::grid::read_grids;
use ugo::readout::probe::read_probes;
use ugo::scene::Scene;

#[test]
fn the_daylit_office_receives_the_flux_of_its_window_and_its_components_add_up() {
    let scene = Scene::load(Path::new("cases/daylit-office.toml")).unwrap_or_else(|e| panic!("{e}"));
    let model = Model::build(&scene, &ugo::progress::Silent).expect("fits");
    let sky = scene.sky.as_ref().expect("a sky");
    let outside = sky.zenith_luminance * (PI / 6.0 + 4.0 / 9.0) + PI / 2.0 * sky.ground_luminance();
    let expected = 3.0 * 1.5 * outside;
    let landed = model.direct.intercepted[0];
    eprintln!("window flux: {landed:.2} lm landed, {expected:.2} lm through the opening");
    assert!((landed / expected - 1.0).abs() < 5e-3, "{landed} against {expected}");

    let x = solve_model(&model, scene.solver.method);
    let field = Field::from_unknowns(&x, model.kernel.cells());
    let probes = read_probes(&scene.probes, &model, &field, &Silent);
    let grids = read_grids(&scene.grids, &model, &field, &Silent);
    let d = read_daylight(&model, sky, &probes, &grids);
    for (p, x) in probes.iter().zip(&d.probes) {
        eprintln!(
            "{:<8} SC {:.3} ERC {:.3} IRC {:.3} DF {:.3} %",
            p.name, x.sky_component, x.externally_reflected, x.internally_reflected, x.daylight_factor
        );
        let sum = x.sky_component + x.externally_reflected + x.internally_reflected;
        assert!((sum - x.daylight_factor).abs() < 1e-9 * x.daylight_factor, "{}: components add up", p.name);
        assert!(x.internally_reflected > 0.0, "{}", p.name);
        match p.name.as_str() {
            "ceiling" => assert!(x.sky_component == 0.0 && x.externally_reflected > 0.0),
            _ => assert!(x.sky_component > 0.0 && x.externally_reflected == 0.0, "{} is below the sill", p.name),
        }
    }
    let front = &d.probes[0];
    assert!(
        front.daylight_factor > d.probes[1].daylight_factor
            && d.probes[1].daylight_factor > d.probes[2].daylight_factor
    );
    let st = stats(&d.grid_factor(0), &grids[0]);
    eprintln!(
        "work plane: DF_avg {:.3} %, DF_min {:.3} %, DF_max {:.3} %, U0 {:.3}",
        st.average, st.min, st.max, st.uniformity
    );
    assert!(st.min <= st.average && st.average <= st.max && (st.uniformity - st.min / st.average).abs() < 1e-12);
    for (x, e) in d.grids[0].iter().zip(&grids[0].illuminance) {
        assert!((x.daylight_factor - 100.0 * e / 10_000.0).abs() < 1e-12);
        let sum = x.sky_component + x.externally_reflected + x.internally_reflected;
        assert!((sum - x.daylight_factor).abs() < 1e-9 * x.daylight_factor, "a grid point's components add up");
    }
}
