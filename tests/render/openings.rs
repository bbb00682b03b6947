//! The sky and the ground seen through a `[[window]]` opening: a camera ray that leaves the
//! scene through it reads the CIE sky's luminance in its direction above the horizon and
//! the ground's `ρ_g E_h/π` below it, times the glazing's `τ(θ)`, in every shading; a
//! surface in the way, or a ray that leaves elsewhere, shows no sky.

use super::{lit_scene, sample_mean};
use crate::support::{lambert, rectangle, surface};
use glam::DVec3;
use ugo::geometry::ConvexPolygon;
use ugo::luminaire::{Light, Source};
use ugo::random::Rng;
use ugo::render::{Shading, render};
use ugo::scene::Camera;
use ugo::sky::{Brightness, Distribution, Glazing, Opening, Sky};

/// The CIE overcast sky of zenith luminance 1000 cd/m² over a ground of reflectance 0.2.
const ZENITH: f64 = 1000.0;
const GROUND: f64 = 0.2;

/// The CIE traditional overcast sky, `L_z (1 + 2 cos Z)/3`, and below the horizon the
/// ground lit by its horizontal illuminance `E_h = (7π/9) L_z`: `ρ_g E_h/π`.
fn cie_overcast(l: DVec3) -> f64 {
    if l.y > 0.0 { ZENITH * (1.0 + 2.0 * l.y) / 3.0 } else { GROUND * ZENITH * 7.0 / 9.0 }
}

fn window(polygon: ConvexPolygon, glazing: Option<Glazing>) -> Source {
    let sky = Sky::new(Distribution::Overcast, DVec3::Y, Brightness::Zenith(ZENITH), GROUND, 0.0);
    Source { name: "window".into(), light: Light::Window { window: Opening { polygon, glazing }, sky }, dimmed: 1.0 }
}

fn camera(look_at: DVec3, up: DVec3, fov_deg: f64) -> Camera {
    Camera { name: "out".into(), position: DVec3::ZERO, look_at, up, fov_deg, resolution: [8, 8], samples: 4 }
}

/// A black square behind the camera (a scene needs a surface), facing it.
fn behind() -> Vec<ugo::geometry::Surface> {
    vec![surface("back", rectangle([-1.0, -1.0, -3.0], [2.0, 0.0, 0.0], [0.0, 2.0, 0.0]), 0, false, None)]
}

/// A 4 × 4 m opening 2 m above the camera.
fn roof() -> ConvexPolygon {
    ConvexPolygon::quad(
        DVec3::new(-2.0, 2.0, -2.0),
        DVec3::new(2.0, 2.0, -2.0),
        DVec3::new(2.0, 2.0, 2.0),
        DVec3::new(-2.0, 2.0, 2.0),
    )
}

#[test]
fn a_camera_looking_up_through_a_roof_opening_reads_the_overcast_sky_in_every_shading() {
    let mut lit = lit_scene(vec![lambert("black", 0.0)], behind(), vec![window(roof(), None)]);
    let view = camera(DVec3::Y, DVec3::Z, 30.0);
    let expected = sample_mean(&view, cie_overcast);
    for shading in [Shading::Flat, Shading::Smooth, Shading::Gather { rays: 16 }] {
        lit.set_shading(shading);
        let image = render(&lit, &view);
        for (i, (l, e)) in image.luminance.iter().zip(&expected).enumerate() {
            assert!((l - e).abs() <= 1e-9 * e, "{shading:?}, pixel {i}: {l} cd/m², the CIE sky {e}");
        }
    }
    let zenith = lit.luminance_along(DVec3::ZERO, DVec3::Y, 0, &mut Rng::keyed(1));
    assert!((zenith - ZENITH).abs() < 1e-9 * ZENITH, "zenith {zenith}");
}

#[test]
fn a_camera_looking_out_of_a_glazed_window_reads_the_horizon_and_the_ground_times_the_glass() {
    let wall = ConvexPolygon::quad(
        DVec3::new(-2.0, -2.0, 2.0),
        DVec3::new(-2.0, 2.0, 2.0),
        DVec3::new(2.0, 2.0, 2.0),
        DVec3::new(2.0, -2.0, 2.0),
    );
    let glass = Glazing::Cie171;
    let lit = lit_scene(vec![lambert("black", 0.0)], behind(), vec![window(wall, Some(glass))]);
    let image = render(&lit, &camera(DVec3::Z, DVec3::Y, 40.0));
    let seen = |l: DVec3| cie_overcast(l) * glass.transmittance(l.z);
    let expected = sample_mean(&camera(DVec3::Z, DVec3::Y, 40.0), seen);
    for (i, (l, e)) in image.luminance.iter().zip(&expected).enumerate() {
        assert!((l - e).abs() <= 1e-9 * e, "pixel {i}: {l} cd/m², expected {e}");
    }
    let mut rng = Rng::keyed(1);
    let just_above = DVec3::new(0.0, 1e-6, 1.0).normalize();
    let horizon = lit.luminance_along(DVec3::ZERO, just_above, 0, &mut rng);
    let tau = glass.transmittance(1.0);
    assert!(
        (horizon - tau * ZENITH / 3.0).abs() < 1e-5 * horizon,
        "horizon {horizon}, τ L_z/3 = {}",
        tau * ZENITH / 3.0
    );
    let ground = lit.luminance_along(DVec3::ZERO, DVec3::new(0.0, -0.2, 1.0).normalize(), 0, &mut rng);
    let erc = tau * GROUND * ZENITH * 7.0 / 9.0;
    assert!((ground / erc - 1.0).abs() < 0.05, "ground {ground}, about τ ρ_g E_h/π = {erc}");
}

#[test]
fn a_surface_in_the_way_hides_the_sky_and_a_ray_leaving_elsewhere_sees_none() {
    // A black ceiling panel at 1 m under the opening, facing down.
    let panel = surface("panel", rectangle([-0.5, 1.0, -0.5], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]), 0, false, None);
    let lit = lit_scene(vec![lambert("black", 0.0)], vec![panel], vec![window(roof(), None)]);
    let mut rng = Rng::keyed(1);
    assert_eq!(lit.luminance_along(DVec3::ZERO, DVec3::Y, 0, &mut rng), 0.0, "the panel hides the sky");
    let beside = DVec3::new(0.8, 1.0, 0.0).normalize();
    assert!(lit.luminance_along(DVec3::ZERO, beside, 0, &mut rng) > 0.0, "the sky beside the panel");
    assert_eq!(lit.luminance_along(DVec3::ZERO, -DVec3::Y, 0, &mut rng), 0.0, "no opening below");
}
