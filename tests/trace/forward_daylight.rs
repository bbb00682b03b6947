//! Light tracing from the sky and the sun through the openings (`src/trace/daylight_photons.rs`)
//! against the deterministic source term, patch by patch. In the daylit office with black
//! surfaces every photon is absorbed where it lands, so the forward estimate of each patch's
//! incident illuminance is the direct light through the window, which the solve integrates
//! over the patch apart (`luminaire::patch_lights`: the sky piece by piece with Lambert's
//! contour integral, the sun's beam cut along its shadows, both through the glass): the two
//! must agree within the photons' standard errors (the solve's own error, about 0.3 % for the
//! sky, stays well below them at this photon count).

use std::f64::consts::PI;
use std::path::Path;
use ugo::model::Model;
use ugo::progress::Silent;
use ugo::scene::Scene;
use ugo::trace::{TraceOptions, World, agreement, trace_photons};

/// The daylit office, black, at uniform 1 m patches, with its text changed by `edits`.
fn black_office(edits: &[(&str, &str)]) -> Scene {
    let path = Path::new("cases/daylit-office.toml");
    let mut text =
        std::fs::read_to_string(path).unwrap().replace("patch_size = 0.25", "patch_size = 1.0\nkernel = \"uniform\"");
    for reflectance in ["0.7", "0.5", "0.2"] {
        let from = format!("\"lambert\"\nreflectance = {reflectance}");
        text = text.replace(&from, "\"lambert\"\nreflectance = 0.0");
    }
    for (from, to) in edits {
        assert!(text.contains(from), "{from}");
        text = text.replace(from, to);
    }
    Scene::parse(path, text).unwrap_or_else(|e| panic!("{e}"))
}

/// Traces `photons` photons and compares every patch's incident illuminance with the solve's
/// direct light, and the flux landed on all of them.
fn forward_against_direct(scene: &Scene, photons: u64, label: &str) {
    let model = Model::build(scene, &Silent).expect("fits");
    let direct: Vec<f64> = (0..model.mesh.len())
        .map(|i| {
            let k = model.kernel.directions.len();
            PI * model.direct.arriving[i * k..(i + 1) * k].iter().sum::<f64>()
        })
        .collect();
    let world = World::new(scene, model.mesh.clone());
    assert!(!world.daylight.is_empty(), "the window emits photons");
    let estimate = trace_photons(&world, &model.kernel.directions, photons, &TraceOptions::default(), &|_| {});
    let a = agreement(&direct, &estimate.illuminance, &estimate.illuminance_error);
    let area = |i: usize| model.mesh.patches[i].exposed;
    let landed = |e: &[f64]| (0..e.len()).map(|i| e[i] * area(i)).sum::<f64>();
    let (solved, traced) = (landed(&direct), landed(&estimate.illuminance));
    let error = (0..direct.len()).map(|i| (estimate.illuminance_error[i] * area(i)).powi(2)).sum::<f64>().sqrt();
    eprintln!(
        "{label}, {photons} photons, {} patches: {a}; landed: solve {solved:.2} lm, forward {traced:.2} (± {error:.2}, \
         independent bins)",
        model.mesh.len()
    );
    assert_eq!(a.unsampled_different, 0, "{label}: a patch lit in the solve got no photon");
    assert!((0.7..1.3).contains(&a.rms_z), "{label}: rms z {}", a.rms_z);
    assert!(a.max_abs_z < 4.5 && a.mean_z.abs() < 0.5, "{label}: max |z| {}, mean z {}", a.max_abs_z, a.mean_z);
    assert!((solved - traced).abs() < 4.0 * error + 3e-3 * solved, "{label}: landed {solved} against {traced}");
}

#[test]
fn photons_from_the_overcast_sky_land_as_the_solve_takes_the_window_s_light() {
    forward_against_direct(&black_office(&[]), 2_000_000, "overcast, open window");
}

#[test]
fn photons_from_the_sun_through_glass_land_as_the_solve_takes_its_beam() {
    let sunny = [
        ("type = \"overcast\"", "type = \"clear\""),
        ("ground_reflectance = 0.2\n", "ground_reflectance = 0.2\nsun_illuminance = 50000.0\n"),
        (
            "edge_v = [0.0, 1.5, 0.0]\n",
            "edge_v = [0.0, 1.5, 0.0]\ntransmittance = 0.8\npanes = 2\nmaintenance_factor = 0.9\n",
        ),
    ];
    forward_against_direct(&black_office(&sunny), 2_000_000, "clear sky and sun, two panes");
}
