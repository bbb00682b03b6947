//! The backward reference against the deterministic image of the same view: the Cornell
//! box at 0.1 m patches (K = 1) through the study camera of `docs/experiments.md` (64×64
//! pixels, no pixel sees the lamp). The error of the solve beyond the reference's noise,
//! `√(‖x − m‖² − ‖σ‖²)/‖m‖`, must lie within the discretization error that the study
//! measured at this patch size against a 16,384-path reference (flat shading) — and the
//! same check must fail for an image that misses most of the light (one reflection only),
//! so it can tell.

use crate::support::build;
use glam::DVec3;
use std::path::Path;
use ugo::render::trace_camera;
use ugo::render::{LitScene, render};
use ugo::scene::{Camera, Scene};
use ugo::trace::{TraceOptions, World, agreement};

/// The study's error beyond noise of the flat image at h = 0.1 m (docs/experiments.md):
/// 12.6 % against the 16,384-path reference.
const STUDY_ERROR: f64 = 0.126;

/// Room for the test reference's own uncertainty (128 paths per pixel: its error beyond
/// noise scatters by a few per cent of itself).
const MARGIN: f64 = 1.2;

pub fn study_camera() -> Camera {
    Camera {
        name: "study".into(),
        position: DVec3::new(0.278, 0.2, -0.8),
        look_at: DVec3::new(0.278, 0.2, 0.5592),
        up: DVec3::Y,
        fov_deg: 28.0,
        resolution: [64, 64],
        samples: 64,
    }
}

#[test]
fn backward_reference_and_deterministic_image_agree_within_the_discretization_error() {
    let mut scene = Scene::load(Path::new("cases/cornell-box.toml")).unwrap();
    scene.discretization.patch_size = 0.1;
    let model = build(&scene);
    let x = crate::support::solve(&model);
    let camera = study_camera();
    let materials = scene.materials.iter().map(|m| m.model.clone()).collect();
    let lit = LitScene::new(model.mesh.clone(), model.kernel.directions.clone(), x, materials);
    let image = render(&lit, &camera);
    let world = World::new(&scene, model.mesh.clone());
    let traced = trace_camera(&world, &camera, 128, &TraceOptions::default(), &|_| {});
    let a = agreement(&image.luminance, &traced.mean.luminance, &traced.standard_error.luminance);
    eprintln!(
        "backward vs flat image, Cornell box h = 0.1: error beyond noise {:.4} (L2 {:.4}, noise {:.4}, L1 {:.4}), rms z {:.2}, {:.2} s",
        a.excess_l2, a.relative_l2, a.noise_l2, a.relative_l1, a.rms_z, traced.seconds
    );
    let first =
        trace_camera(&world, &camera, 32, &TraceOptions { max_order: Some(1), ..TraceOptions::default() }, &|_| {});
    let b = agreement(&image.luminance, &first.mean.luminance, &first.standard_error.luminance);
    eprintln!("against one reflection only: error beyond noise {:.4}", b.excess_l2);
    assert!(a.excess_l2 <= MARGIN * STUDY_ERROR, "error beyond noise {} over the study's {STUDY_ERROR}", a.excess_l2);
    assert!(b.excess_l2 > MARGIN * STUDY_ERROR, "the check cannot tell a truncated image: {}", b.excess_l2);
}
