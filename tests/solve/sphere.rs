//! The integrating sphere: the reflected illuminance on the wall is uniform,
//! `E_ind = ρΦ / (A (1 − ρ (1 − f)))`, `f` the wall's form factor to the black bulb; with
//! the uniform kernel and through the hierarchy (issue 14.4), within the same bounds.

use std::f64::consts::PI;
use std::path::Path;
use ugo::kernel::Factored;
use ugo::model::Model;
use ugo::scene::{Hierarchical, KernelKind, Scene};
use ugo::solve::{SolveParams, successive_approximation};

/// The bulb's form factor seen from the wall and the wall's worst relative departure from
/// `E_ind`, with the case's kernel replaced by `kernel` (patch size `patch_size`).
fn sphere(kernel: KernelKind, patch_size: f64) -> (f64, f64) {
    let mut scene = Scene::load(Path::new("cases/integrating-sphere.toml")).unwrap();
    scene.discretization.kernel = kernel;
    scene.discretization.patch_size = patch_size;
    let model = Model::build(&scene, &ugo::progress::Silent).unwrap();
    let params = SolveParams { tolerance: 1e-10, max_iterations: 1000, ..SolveParams::default() };
    let (x, _) = successive_approximation(&Factored::new(&model.kernel), &model.l0, &params, &mut |_, _| {}).unwrap();
    let transport = |v: &[f64]| {
        let mut y = vec![0.0; v.len()];
        model.kernel.apply_transport(v, &mut y);
        y
    };
    let (total, direct) = (transport(&x), transport(&model.l0));
    let p = &model.mesh.patches;
    // G applied to the bulb's indicator: each wall patch's factor to the bulb
    let to_bulb = transport(&p.iter().map(|q| f64::from(u8::from(q.surface == 1))).collect::<Vec<_>>());
    let wall: Vec<usize> = (0..p.len()).filter(|&i| p[i].surface == 0).collect();
    let area: f64 = wall.iter().map(|&i| p[i].area).sum();
    let f = wall.iter().map(|&i| p[i].area * to_bulb[i]).sum::<f64>() / area;
    let (rho, flux) = (0.8, 1000.0);
    let expected = rho * flux / (area * (1.0 - rho * (1.0 - f)));
    let worst = wall.iter().map(|&i| (PI * (total[i] - direct[i]) / expected - 1.0).abs()).fold(0.0, f64::max);
    eprintln!(
        "sphere, {}: {} wall patches, A = {area:.4} m², f = {f:.5}, E_ind = {expected:.3} lx, worst {worst:.2e}",
        kernel.name(),
        wall.len()
    );
    (f, worst)
}

#[test]
#[ignore = "about a minute: make test-long"]
fn indirect_illuminance_on_the_wall_is_uniform_and_as_predicted() {
    let (f, worst) = sphere(KernelKind::Uniform, 0.1);
    assert!((f / 0.0025 - 1.0).abs() < 0.2, "bulb form factor {f}");
    assert!(worst < 1e-2, "indirect illuminance varies by {worst}");
}

#[test]
fn through_the_hierarchy_too() {
    let (f, worst) = sphere(
        KernelKind::Hierarchical(Hierarchical {
            root_size: 0.4,
            link_tolerance: 1e-2,
            passes: ugo::scene::Hierarchical::DEFAULT_PASSES,
        }),
        0.1,
    );
    assert!((f / 0.0025 - 1.0).abs() < 0.2, "bulb form factor {f}");
    assert!(worst < 1e-2, "indirect illuminance varies by {worst}");
}
