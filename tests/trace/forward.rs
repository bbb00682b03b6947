//! The forward estimate of the discrete field against the direct solve of the same
//! discretization, on a scene where the discretization is exact in expectation.
//!
//! A black square lamp (1000 cd/m²) hangs 1 m above a floor made of a grey Lambertian
//! half (ρ = 0.6) and a two-sided opal half (ρ = 0.3, τ = 0.4), K = 16 cells. Light
//! reflects at most once: from the floor plane it can only reach the black lamp or leave
//! the scene, and what the opal transmits leaves downwards. For one reflection of a
//! uniform Lambertian source off a Lambertian patch the linear system is exact,
//! `L(i,k) = r F_{i→lamp} L0` in every cell, so the two agree to within the form factors'
//! quadrature error, measured at 1e8 photons (docs/tracing.md) far below the standard
//! errors of the photon count used here. The test checks the flux-to-luminance scaling
//! `A_i μ_k`, the cell lookup in each patch's frame, and transmission into the twin.

use crate::support::{build_with, lambert, material, rectangle, scene, solve, surface};
use ugo::directions::DirectionSet;
use ugo::geometry::{Emission, Surface};
use ugo::material::MaterialModel;
use ugo::scene::Scene;
use ugo::trace::{TraceOptions, World, agreement, trace_photons};

pub fn lamp_over_floor() -> Scene {
    let opal = MaterialModel::Lambert { reflectance: 0.3, transmittance: 0.4 };
    let mut two_sided =
        surface("opal floor", rectangle([0.0, 0.0, 0.0], [0.0, 0.0, 2.0], [1.0, 0.0, 0.0]), 2, false, None);
    two_sided.two_sided = true;
    let surfaces: Vec<Surface> = vec![
        surface(
            "lamp",
            rectangle([-0.25, 1.0, 0.75], [0.5, 0.0, 0.0], [0.0, 0.0, 0.5]),
            0,
            false,
            Some(Emission::Luminance(1000.0)),
        ),
        surface("grey floor", rectangle([-1.0, 0.0, 0.0], [0.0, 0.0, 2.0], [1.0, 0.0, 0.0]), 1, false, None),
        two_sided,
    ];
    scene(vec![lambert("black", 0.0), lambert("grey", 0.6), material("opal", opal)], surfaces, 0.25)
}

#[test]
fn forward_estimate_agrees_with_the_direct_solve_of_the_same_discretization() {
    let scene = lamp_over_floor();
    let directions = DirectionSet::hemisphere(16);
    let model = build_with(&scene, directions.clone());
    let x = solve(&model);
    let world = World::new(&scene, model.mesh.clone());
    let photons: u64 = std::env::var("UGO_TEST_PHOTONS").ok().and_then(|p| p.parse().ok()).unwrap_or(1_000_000);
    let estimate = trace_photons(&world, &directions, photons, &TraceOptions::default(), &|_| {});
    let a = agreement(&x, &estimate.luminance, &estimate.luminance_error);
    eprintln!("forward vs direct, {photons} photons, {} patches × K = 16: {a}", model.mesh.len());
    // Overall: the scattered flux Σ A_i μ_k (L − L0) of the solve against the estimate's.
    let k = directions.len();
    let solved: f64 = (0..x.len())
        .map(|b| model.mesh.patches[b / k].area * directions.cells()[b % k].projected * (x[b] - model.l0[b]))
        .sum();
    let (flux, error) = estimate.scattered;
    let z = (solved - flux) / error;
    eprintln!("scattered flux: solve {solved:.5} lm, forward {flux:.5} ± {error:.5} lm, z {z:+.2}");
    assert!(z.abs() < 3.0, "scattered flux z {z}");
    let reflecting = x.iter().zip(&model.l0).filter(|(l, l0)| l > l0).count();
    assert_eq!(a.compared, reflecting, "every bin that reflects light in the solve got photons");
    assert_eq!(a.unsampled_different, 0, "bins without photons hold just the emission in the solve");
    assert!((0.85..1.15).contains(&a.rms_z), "rms z {}", a.rms_z);
    assert!(a.max_abs_z < 5.0 && a.beyond_3 < 0.01, "max |z| {}, beyond 3σ {}", a.max_abs_z, a.beyond_3);
}

#[test]
fn leaf_errors_weigh_the_precise_bins_by_area() {
    use ugo::trace::leaf_errors;
    // four bins: two precise (σ/m = 1e-3), one too noisy, one without an estimate
    let values = [1.01, 2.0 * 0.9, 3.0 * 1.5, 7.0];
    let mean = [1.0, 2.0, 3.0, 0.0];
    let error = [1e-3, 2e-3, 0.3, 0.0];
    let areas = [3.0, 1.0, 4.0, 2.0];
    let e = leaf_errors(&values, &mean, &error, &areas, 5e-3).expect("two precise bins");
    assert_eq!(e.bins, 2);
    assert!((e.area_share - 0.4).abs() < 1e-12, "{e:?}");
    assert!((e.mean - (3.0 * 0.01 + 1.0 * 0.1) / 4.0).abs() < 1e-12, "{e:?}");
    // 95 % of the 4 m² lie at or below 0.1 (0.01 covers only 75 %)
    assert!((e.p95 - 0.1).abs() < 1e-12 && (e.largest.0 - 0.1).abs() < 1e-12 && e.largest.1 == 1, "{e:?}");
    assert!(leaf_errors(&values, &mean, &error, &areas, 1e-4).is_none());
}
