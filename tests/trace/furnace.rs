//! The white furnace `L = L0/(1 − ρ)` reproduced by both estimators within their standard
//! errors: per value (about 0.27 % beyond 3σ, rms z near 1, so the errors are honest) and
//! overall (the mean of all pixels, or the total scattered flux, within 3 standard errors).

use crate::support::furnace;
use glam::DVec3;
use ugo::directions::DirectionSet;
use ugo::geometry::Mesh;
use ugo::material::MaterialModel;
use ugo::render::trace_camera;
use ugo::scene::{Camera, Scene};
use ugo::trace::{TraceOptions, World, agreement, trace_photons};

const EXACT: f64 = 5.0;

fn world(scene: &Scene) -> World {
    World::new(scene, Mesh::build(&scene.surfaces, scene.discretization.patch_size))
}

fn inside() -> Camera {
    Camera {
        name: "inside".into(),
        position: DVec3::new(0.5, 0.5, 0.2),
        look_at: DVec3::new(0.5, 0.4, 1.0),
        up: DVec3::Y,
        fov_deg: 100.0,
        resolution: [16, 16],
        samples: 1,
    }
}

/// `z` of the mean of independent estimates `m ± s` against `EXACT`.
fn overall_z(mean: &[f64], error: &[f64]) -> f64 {
    let n = mean.len() as f64;
    let m = mean.iter().sum::<f64>() / n;
    let s = error.iter().map(|e| e * e).sum::<f64>().sqrt() / n;
    (m - EXACT) / s
}

/// Per-value agreement with `EXACT`, and the overall `z` (given, or of the mean of
/// independent values).
fn check(what: &str, mean: &[f64], error: &[f64], overall: Option<f64>) {
    let exact = vec![EXACT; mean.len()];
    let a = agreement(&exact, mean, error);
    let z = overall.unwrap_or_else(|| overall_z(mean, error));
    eprintln!(
        "{what}: {} values, overall z {z:+.2}, rms z {:.3}, max |z| {:.2}, beyond 3σ {:.2} %, noise {:.2e}",
        a.compared,
        a.rms_z,
        a.max_abs_z,
        100.0 * a.beyond_3,
        a.noise_l2
    );
    assert_eq!(a.compared, mean.len(), "every value has a positive standard error");
    assert!(z.abs() < 3.0, "overall z {z}");
    // Per-value errors are themselves estimated (from 256 samples of a skewed distribution).
    assert!((0.8..1.25).contains(&a.rms_z), "rms z {} (standard errors are not honest)", a.rms_z);
    assert!(a.beyond_3 < 0.02, "{:.3} beyond 3σ", a.beyond_3);
}

#[test]
fn backward_furnaces_read_five_in_every_pixel() {
    for (name, model) in [
        ("lambert", MaterialModel::Lambert { reflectance: 0.8, transmittance: 0.0 }),
        ("mirror", MaterialModel::Mirror { reflectance: 0.8 }),
    ] {
        let mut scene = furnace(1.0, 0.8, 1.0, 0.25);
        scene.materials[0].model = model;
        let image = trace_camera(&world(&scene), &inside(), 256, &TraceOptions::default(), &|_| {});
        check(&format!("backward {name} furnace"), &image.mean.luminance, &image.standard_error.luminance, None);
    }
}

#[test]
fn forward_furnace_reads_five_in_every_bin() {
    let scene = furnace(1.0, 0.8, 1.0, 0.25);
    let directions = DirectionSet::hemisphere(4);
    let world = world(&scene);
    let estimate = trace_photons(&world, &directions, 400_000, &TraceOptions::default(), &|_| {});
    // Scattered flux: ρ/(1 − ρ) = 4 times the emitted flux.
    let (flux, error) = estimate.scattered;
    let z = (flux - 4.0 * world.emitters.flux()) / error;
    eprintln!("forward furnace: scattered flux {flux:.4} ± {error:.4} lm, z {z:+.2}");
    check("forward lambert furnace, K = 4", &estimate.luminance, &estimate.luminance_error, Some(z));
    let illuminance = estimate.illuminance.iter().map(|e| e * 0.8 / std::f64::consts::PI + 1.0).collect::<Vec<_>>();
    let errors = estimate.illuminance_error.iter().map(|e| e * 0.8 / std::f64::consts::PI).collect::<Vec<_>>();
    check("forward furnace illuminance, as L0 + ρE/π", &illuminance, &errors, Some(z));
}
