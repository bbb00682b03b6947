//! The integrating sphere: the reflected illuminance on the wall is uniform,
//! `E_ind = ρΦ / (A (1 − ρ (1 − f)))`, `f` the wall's form factor to the black bulb.

use std::f64::consts::PI;
use std::path::Path;
use ugo::kernel::Factored;
use ugo::model::{Model, ModelOptions};
use ugo::scene::Scene;
use ugo::solve::{SolveParams, successive_approximation};

#[test]
fn indirect_illuminance_on_the_wall_is_uniform_and_as_predicted() {
    let scene = Scene::load(Path::new("cases/integrating-sphere.toml")).unwrap();
    let model = Model::build(&scene, &ModelOptions::of(&scene), &ugo::progress::Silent).unwrap();
    let params = SolveParams { tolerance: 1e-10, max_iterations: 1000, ..SolveParams::default() };
    let (x, _) = successive_approximation(&Factored::new(&model.kernel), &model.l0, &params, &mut |_, _| {}).unwrap();
    let (mut total, mut direct) = (vec![0.0; x.len()], vec![0.0; x.len()]);
    model.kernel.apply_transport(&x, &mut total);
    model.kernel.apply_transport(&model.l0, &mut direct);

    let p = &model.mesh.patches;
    let wall: Vec<usize> = (0..p.len()).filter(|&i| p[i].surface == 0).collect();
    let area: f64 = wall.iter().map(|&i| p[i].area).sum();
    let to_bulb = |i: usize| -> f64 {
        let row = model.kernel.g.as_double().expect("double precision by default").outer_view(i).unwrap();
        row.iter().filter(|(j, _)| p[*j].surface == 1).map(|(_, v)| v).sum()
    };
    let f = wall.iter().map(|&i| p[i].area * to_bulb(i)).sum::<f64>() / area;
    let (rho, flux) = (0.8, 1000.0);
    let expected = rho * flux / (area * (1.0 - rho * (1.0 - f)));
    let worst = wall.iter().map(|&i| (PI * (total[i] - direct[i]) / expected - 1.0).abs()).fold(0.0, f64::max);
    eprintln!(
        "sphere: {} wall patches, A = {area:.4} m², f = {f:.5}, E_ind = {expected:.3} lx, worst {worst:.2e}",
        wall.len()
    );
    assert!((f / 0.0025 - 1.0).abs() < 0.2, "bulb form factor {f}");
    assert!(worst < 1e-2, "indirect illuminance varies by {worst}");
}
