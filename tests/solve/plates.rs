//! Parallel plates: direct illuminance through the whole pipeline, mean and at a probe.

use crate::support::corner_factor;
use glam::DVec3;
use std::f64::consts::PI;
use std::path::Path;
use ugo::kernel::Factored;
use ugo::model::Model;
use ugo::progress::Silent;
use ugo::readout::field::Field;
use ugo::readout::probe::read_probes;
use ugo::scene::Scene;
use ugo::solve::{SolveParams, successive_approximation};

#[test]
fn receiver_illuminance_is_pi_l_f() {
    let scene = Scene::load(Path::new("cases/parallel-plates.toml")).unwrap();
    let model = Model::build(&scene, &ugo::progress::Silent).unwrap();
    let params = SolveParams { tolerance: 1e-10, max_iterations: 100, ..SolveParams::default() };
    let (x, _) = successive_approximation(&Factored::new(&model.kernel), &model.l0, &params, &mut |_, _| {}).unwrap();
    let mut gx = vec![0.0; x.len()];
    model.kernel.apply_transport(&x, &mut gx);
    let p = &model.mesh.patches;
    let (mut flux, mut area) = (0.0, 0.0);
    for i in (0..p.len()).filter(|&i| p[i].surface == 1) {
        flux += PI * gx[i] * p[i].area;
        area += p[i].area;
    }
    let mean = flux / area;
    let exact = PI * 1000.0 * 0.1998249;
    eprintln!("plates: mean E = {mean:.4} lx (exact {exact:.4})");
    assert!((mean / exact - 1.0).abs() < 5e-3);

    let field = Field::from_unknowns(&x, 1);
    let probe = &read_probes(&scene.probes, &model, &field, &Silent)[0];
    let centre = PI * 1000.0 * 4.0 * corner_factor(0.5, 0.5, 1.0);
    assert!(probe.patch.is_some(), "the probe lies on the receiver");
    assert_eq!(probe.normal, DVec3::new(0.0, 0.0, -1.0));
    assert!((probe.illuminance / centre - 1.0).abs() < 1e-9, "{} vs {centre}", probe.illuminance);
    assert_eq!(probe.luminance, 0.0, "a black receiver reflects nothing");
}
