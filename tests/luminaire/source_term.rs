//! The luminaires' light as the source term: conserved in closed rooms for any
//! distribution, reflected by any material block, cast into shadows, read exactly by
//! probes, and added to the surfaces' own emission.

use super::{point, table};
use crate::support::{build, build_with, lambert, material, rectangle, scene, surface};
use glam::DVec3;
use std::f64::consts::PI;
use ugo::directions::DirectionSet;
use ugo::geometry::{Emission, Shape};
use ugo::kernel::Factored;
use ugo::luminaire::direct_light;
use ugo::material::MaterialModel;
use ugo::photometry::Distribution;
use ugo::progress::Silent;
use ugo::readout::energy::EnergyBalance;
use ugo::readout::field::Field;
use ugo::readout::illuminance::patch_illuminance;
use ugo::readout::probe::read_probes;
use ugo::scene::{Probe, Scene};
use ugo::solve::{Method, SolveParams, System, solve};

/// A closed 3 × 2.5 × 4 m room of reflectance `rho`, seen from inside.
fn room(rho: f64, patch: f64) -> Scene {
    let shape = Shape::Box { min: DVec3::ZERO, max: DVec3::new(3.0, 2.5, 4.0), rotate_y_deg: 0.0 };
    scene(vec![lambert("grey", rho)], vec![surface("room", shape, 0, true, None)], patch)
}

fn solved(model: &ugo::model::Model) -> Vec<f64> {
    let areas: Vec<f64> = model.mesh.patches.iter().map(|p| p.area).collect();
    let factored = Factored::new(&model.kernel);
    let system = System::of(&model.kernel, &factored, None, &areas, &model.l0);
    let params = SolveParams { tolerance: 1e-11, max_iterations: 10_000, ..SolveParams::default() };
    solve(Method::Gmres { restart: 30 }, &system, &params, &mut |_, _| {}).unwrap().0
}

#[test]
fn anisotropic_files_in_a_closed_room_land_whole_and_balance() {
    for (file, aim) in
        [("c-full-2019.ies", DVec3::new(0.2, -1.0, 0.1)), ("b-front-2002.ies", DVec3::new(1.0, -0.3, 0.4))]
    {
        let mut s = room(0.6, 0.5);
        s.luminaires.push(point("lamp", DVec3::new(1.1, 1.7, 2.3), aim, table(file)));
        let model = build(&s);
        let flux = model.sources[0].flux().unwrap();
        let landed = model.direct.intercepted[0] / flux - 1.0;
        let x = solved(&model);
        let e = EnergyBalance::of(&model, &x, 1);
        eprintln!(
            "{file}: Φ = {flux:.3} lm, landed {landed:+.2e}, imbalance {:.1e}, escaped {:.1e} lm",
            e.imbalance / e.emitted,
            e.escaped
        );
        assert!(landed.abs() < 1e-3, "{file}: the patches intercept {landed:+e} of the flux");
        assert!((e.imbalance / e.emitted).abs() < 1e-8 && e.escaped.abs() < 2e-3 * flux, "{e:?}");
        assert!((e.absorbed / flux - 1.0).abs() < 2e-3, "{e:?}");
    }
}

#[test]
fn light_that_lands_nowhere_escapes() {
    let floor = rectangle([0.0, 0.0, 0.0], [0.0, 0.0, 2.0], [2.0, 0.0, 0.0]);
    let mut s = scene(vec![lambert("grey", 0.5)], vec![surface("floor", floor, 0, false, None)], 0.25);
    s.luminaires.push(point(
        "bulb",
        DVec3::new(1.0, 1.0, 1.0),
        DVec3::NEG_Y,
        Distribution::Isotropic { intensity: 100.0 },
    ));
    let model = build(&s);
    let x = solved(&model);
    let e = EnergyBalance::of(&model, &x, 1);
    let landed = model.direct.intercepted[0];
    assert!((e.emitted - 400.0 * PI).abs() < 1e-9, "{e:?}");
    assert!((e.absorbed - 0.5 * landed).abs() < 1e-6 * landed, "half of what lands is absorbed: {e:?}");
    assert!((e.escaped - (400.0 * PI - landed + 0.5 * landed)).abs() < 1e-6 * landed, "{e:?}");
    assert!(e.imbalance.abs() < 1e-9 * e.emitted);
}

#[test]
fn a_lambertian_receiver_gets_rho_e_over_pi_in_every_cell_at_any_k() {
    let floor = rectangle([0.0, 0.0, 0.0], [0.0, 0.0, 2.0], [2.0, 0.0, 0.0]);
    let mut s = scene(vec![lambert("grey", 0.5)], vec![surface("floor", floor, 0, false, None)], 0.5);
    s.luminaires.push(point("lamp", DVec3::new(0.7, 1.5, 1.2), DVec3::NEG_Y, Distribution::Lambertian { peak: 800.0 }));
    let one = build(&s);
    let many = build_with(&s, DirectionSet::hemisphere(16));
    let e = patch_illuminance(&one.direct.arriving, 1);
    for (i, e) in e.iter().enumerate() {
        assert!((one.l0[i] - 0.5 * e / PI).abs() < 1e-12 * e);
        for k in 0..16 {
            assert!((many.l0[i * 16 + k] - one.l0[i]).abs() < 1e-12 * e, "patch {i}, cell {k}");
        }
    }
}

#[test]
fn a_mirror_reflects_the_luminaire_into_the_mirror_cell() {
    let floor = rectangle([0.0, 0.0, 0.0], [0.0, 0.0, 2.0], [2.0, 0.0, 0.0]);
    let mirror = material("mirror", MaterialModel::Mirror { reflectance: 0.8 });
    let mut s = scene(vec![mirror], vec![surface("floor", floor, 0, false, None)], 0.5);
    s.luminaires.push(point(
        "lamp",
        DVec3::new(0.25, 1.0, 0.25),
        DVec3::NEG_Y,
        Distribution::Isotropic { intensity: 100.0 },
    ));
    let directions = DirectionSet::hemisphere(64);
    let model = build_with(&s, directions.clone());
    let e = patch_illuminance(&model.direct.arriving, 64);
    for (i, patch) in model.mesh.patches.iter().enumerate() {
        let l0 = &model.l0[i * 64..(i + 1) * 64];
        let exitance: f64 = l0.iter().zip(directions.cells()).map(|(l, c)| l * c.projected).sum();
        assert!((exitance / (0.8 * e[i]) - 1.0).abs() < 1e-9, "the mirror reflects 80 % of E_s on patch {i}");
        let towards_lamp = (DVec3::new(0.25, 1.0, 0.25) - patch.centroid).normalize();
        let mirrored = 2.0 * towards_lamp.dot(patch.normal) * patch.normal - towards_lamp;
        let expected = directions.lookup(patch.frame().local(mirrored));
        let brightest = (0..64).max_by(|&a, &b| l0[a].total_cmp(&l0[b])).unwrap();
        let lit: Vec<usize> = (0..64).filter(|&k| l0[k] > 0.0).collect();
        assert!(
            lit.contains(&expected) && (brightest == expected || lit.len() > 1),
            "patch {i}: {lit:?}, expected {expected}"
        );
    }
}

/// A 2 × 2 m grey floor in 0.25 m patches, a black 0.5 m strip 1 m above it (x from 0.5 to
/// 1.0 m) and an isotropic 100 cd lamp 2 m above the floor at x = `lamp_x`, z = 1 m.
fn shaded_floor(lamp_x: f64) -> Scene {
    let floor = rectangle([0.0, 0.0, 0.0], [0.0, 0.0, 2.0], [2.0, 0.0, 0.0]);
    let blocker = rectangle([0.5, 1.0, 0.0], [0.0, 0.0, 2.0], [0.5, 0.0, 0.0]);
    let mut s = scene(
        vec![lambert("grey", 0.5), lambert("black", 0.0)],
        vec![surface("floor", floor, 0, false, None), surface("blocker", blocker, 1, false, None)],
        0.25,
    );
    s.luminaires.push(point(
        "lamp",
        DVec3::new(lamp_x, 2.0, 1.0),
        DVec3::NEG_Y,
        Distribution::Isotropic { intensity: 100.0 },
    ));
    s
}

#[test]
fn shadows_are_cast_on_patches_and_at_probes() {
    let mut s = shaded_floor(0.75);
    s.probes.push(Probe::point("shade", DVec3::new(0.75, 0.0, 1.0), DVec3::Y));
    s.probes.push(Probe::point("sun", DVec3::new(1.75, 0.0, 1.0), DVec3::Y));
    let model = build(&s);
    let x = solved(&model);
    let probes = read_probes(&s.probes, &model, &Field::from_unknowns(&x, 1), &Silent);
    assert_eq!(probes[0].direct, 0.0, "behind the blocker");
    let d: f64 = (DVec3::new(1.75, 0.0, 1.0) - DVec3::new(0.75, 2.0, 1.0)).length();
    assert!((probes[1].direct - 100.0 * 2.0 / d.powi(3)).abs() < 1e-9, "I cosθ / r²: {}", probes[1].direct);
    let e = patch_illuminance(&model.direct.arriving, 1);
    for (i, p) in model.mesh.patches.iter().enumerate().filter(|(_, p)| p.surface == 0) {
        let (x, z) = (p.centroid.x, p.centroid.z);
        let exact = |x: f64, z: f64| {
            let r = DVec3::new(x - 0.75, -2.0, z - 1.0);
            100.0 * 2.0 / r.length().powi(3)
        };
        // the blocker (x 0.5–1.0 at 1 m) shades x from 0.25 to 1.25 on the floor
        if x + 0.125 <= 0.25 || x - 0.125 >= 1.25 {
            assert!((e[i] / exact(x, z) - 1.0).abs() < 2e-2, "lit patch at ({x}, {z}): {}", e[i]);
        } else if x - 0.125 >= 0.25 && x + 0.125 <= 1.25 {
            assert_eq!(e[i], 0.0, "shaded patch at ({x}, {z})");
        } else {
            assert!(e[i] > 0.0 && e[i] < exact(x, z), "penumbra patch at ({x}, {z}): {}", e[i]);
        }
    }
}

/// A light scene dims a source (`Source::scaled`): its light on the patches, cut along
/// shadows down to the same limits (`DirectLight::least`), is exactly the factor times its
/// own, though the dimmed pieces carry less flux against those limits.
#[test]
fn a_dimmed_source_is_cut_along_shadows_as_its_own_light() {
    let s = shaded_floor(0.8);
    // the shadow's edges fall at x = 0.2 and 1.2 m, across the 0.25 m patches
    let model = build(&s);
    let light = |sources: &[ugo::luminaire::Source], least: &[f64]| {
        direct_light(sources, &model.mesh, &model.visibility, &model.kernel.directions, least, &model.mirrors).arriving
    };
    // 0.05 lm: the undimmed penumbra pieces of 0.1 lm are cut further, at 0.3 of it not
    let least = vec![0.05; model.mesh.len()];
    let own = light(&model.sources, &least);
    assert_ne!(own, light(&model.sources, &[]), "the limits change the cutting");
    let dimmed: Vec<_> = model.sources.iter().map(|s| s.scaled(0.3)).collect();
    let scaled: Vec<f64> = own.iter().map(|d| 0.3 * d).collect();
    for (a, b) in light(&dimmed, &least).iter().zip(&scaled) {
        assert!((a - b).abs() <= 1e-12 * b.abs(), "dimmed {a} against 0.3 × own {b}");
    }
}

#[test]
fn a_probe_on_a_lit_floor_reads_rho_e_over_pi() {
    let floor = rectangle([0.0, 0.0, 0.0], [0.0, 0.0, 2.0], [2.0, 0.0, 0.0]);
    let mut s = scene(vec![lambert("grey", 0.4)], vec![surface("floor", floor, 0, false, None)], 0.5);
    s.luminaires.push(point("lamp", DVec3::new(0.6, 1.2, 0.9), DVec3::NEG_Y, Distribution::Lambertian { peak: 500.0 }));
    s.probes.push(Probe::point("p", DVec3::new(1.3, 0.0, 0.4), DVec3::Y));
    let model = build(&s);
    let x = solved(&model);
    let probe = &read_probes(&s.probes, &model, &Field::from_unknowns(&x, 1), &Silent)[0];
    let r = DVec3::new(1.3 - 0.6, -1.2, 0.4 - 0.9);
    let exact = 500.0 * (1.2 / r.length()).powi(2) / r.length_squared();
    assert!(probe.patch.is_some());
    assert!((probe.illuminance / exact - 1.0).abs() < 1e-12 && probe.direct == probe.illuminance, "{probe:?}");
    assert!(
        (probe.luminance / (0.4 * exact / PI) - 1.0).abs() < 1e-12,
        "the point's own E, not the patch mean: {probe:?}"
    );
}

#[test]
fn area_emitters_and_luminaires_add_up() {
    let panel = rectangle([0.5, 2.4, 0.5], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]);
    let base = |emit: bool, lamp: bool| {
        let mut s = room(0.5, 1.0);
        s.surfaces.push(surface("panel", panel.clone(), 0, false, emit.then_some(Emission::Luminance(300.0))));
        if lamp {
            s.luminaires.push(point("lamp", DVec3::new(2.0, 1.0, 3.0), DVec3::NEG_Y, table("c-quadrant-1995.ies")));
        }
        s
    };
    let (both, area, lamp) = (build(&base(true, true)), build(&base(true, false)), build(&base(false, true)));
    for ((b, a), l) in both.l0.iter().zip(&area.l0).zip(&lamp.l0) {
        assert!((b - (a + l)).abs() < 1e-12 * b.abs().max(1.0));
    }
    let (xb, xa, xl) = (solved(&both), solved(&area), solved(&lamp));
    let worst = xb.iter().zip(xa.iter().zip(&xl)).map(|(b, (a, l))| (b - a - l).abs() / b).fold(0.0, f64::max);
    assert!(worst < 1e-8, "superposition: {worst}");
}
