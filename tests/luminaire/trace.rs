//! The Monte Carlo estimators with luminaires: backward paths gather them exactly (a floor
//! point reads `ρ E/π`, a probe `E`, with no noise), and photons from an IES luminaire and
//! from the sun agree bin by bin with the direct solve of a scene where the discretization
//! is exact in expectation (light reflects once, off a Lambertian floor: `L(i,k) = ρ E_s(i)/π`).

use super::{point, table};
use crate::support::{build_with, lambert, rectangle, scene, solve, surface};
use glam::DVec3;
use std::f64::consts::PI;
use ugo::directions::DirectionSet;
use ugo::geometry::Mesh;
use ugo::luminaire::LuminaireKind;
use ugo::photometry::Distribution;
use ugo::readout::illuminance::patch_illuminance;
use ugo::scene::{Probe, Scene};
use ugo::trace::{Start, TraceOptions, World, agreement, luminance_along, trace_photons, trace_probes};

fn floor_under(luminaires: Vec<ugo::luminaire::Luminaire>) -> Scene {
    let floor = rectangle([-1.0, 0.0, -1.0], [0.0, 0.0, 2.0], [2.0, 0.0, 0.0]);
    let mut s = scene(vec![lambert("grey", 0.5)], vec![surface("floor", floor, 0, false, None)], 0.25);
    s.luminaires = luminaires;
    s
}

#[test]
fn backward_paths_and_probes_gather_luminaires_exactly() {
    let lamp = DVec3::new(0.2, 1.0, -0.3);
    let mut s = floor_under(vec![point("lamp", lamp, DVec3::NEG_Y, Distribution::Lambertian { peak: 1000.0 })]);
    s.probes.push(Probe::point("on", DVec3::new(0.5, 0.0, 0.4), DVec3::Y));
    let world = World::new(&s, Mesh::build(&s.surfaces, 0.25));
    let exact = |q: DVec3| {
        let r = q - lamp;
        1000.0 * (r.y / r.length()).powi(2) / r.length_squared()
    };
    let q = DVec3::new(0.5, 0.0, 0.4);
    let reading = &trace_probes(&world, &s.probes, 64, &TraceOptions::default(), &|_| {})[0];
    assert!(
        (reading.illuminance.0 / exact(q) - 1.0).abs() < 1e-9 && reading.illuminance.1 < 1e-9 * exact(q),
        "{reading:?}"
    );
    assert!((reading.luminance.0 / (0.5 * exact(q) / PI) - 1.0).abs() < 1e-6, "{reading:?}");
    let mut rng = ugo::random::Rng::stream(7, 0);
    let eye = DVec3::new(-0.4, 0.7, 0.3);
    let (mut rays, target) = (0, DVec3::new(-0.1, 0.0, 0.6));
    let l = luminance_along(
        &world,
        Start::eye(eye, (target - eye).normalize()),
        &mut rng,
        &TraceOptions::default(),
        &mut rays,
    );
    assert!((l / (0.5 * exact(target) / PI) - 1.0).abs() < 1e-6, "{l}");
}

#[test]
fn photons_from_an_ies_luminaire_and_the_sun_agree_with_the_solve() {
    let mut spot = point("spot", DVec3::new(0.3, 0.8, -0.2), DVec3::new(0.4, -1.0, 0.2), table("c-full-2019.ies"));
    let LuminaireKind::Point(p) = &mut spot.kind else { unreachable!() };
    p.rotate_deg = 25.0;
    let sun = ugo::luminaire::Luminaire {
        name: "sun".into(),
        kind: LuminaireKind::Parallel {
            direction: DVec3::new(0.3, -0.8, 0.5).normalize(),
            illuminance: 2000.0,
            glass: Default::default(),
        },
    };
    let s = floor_under(vec![spot, sun]);
    let directions = DirectionSet::hemisphere(16);
    let model = build_with(&s, directions.clone());
    let x = solve(&model);
    let world = World::new(&s, model.mesh.clone());
    let estimate = trace_photons(&world, &directions, 1_000_000, &TraceOptions::default(), &|_| {});
    let a = agreement(&x, &estimate.luminance, &estimate.luminance_error);
    eprintln!(
        "luminaires, forward vs direct: {} bins, rms z {:.3}, max |z| {:.2}, beyond 3σ {:.2} %, relative L1 {:.2e}",
        a.compared,
        a.rms_z,
        a.max_abs_z,
        100.0 * a.beyond_3,
        a.relative_l1
    );
    assert_eq!(a.compared, x.len(), "every bin of the lit floor got photons");
    assert!((0.8..1.2).contains(&a.rms_z) && a.max_abs_z < 5.0, "{a:?}");
    let e = patch_illuminance(&model.direct.arriving, 16);
    let worst = estimate
        .illuminance
        .iter()
        .zip(&estimate.illuminance_error)
        .zip(&e)
        .map(|((m, s), e)| ((m - e) / s).abs())
        .fold(0.0, f64::max);
    assert!(worst < 5.0, "patch illuminance against E_s: worst |z| {worst}");
}
