//! A vertical mirror and the image-source closed form (`docs/mirrors.md`).
//!
//! A black floor (2 × 2 m, `x ∈ [0, 2]`, `z ∈ [−1, 1]`, y up), a mirror wall at `x = 0`
//! (`ρ_s = 0.8`, 1 m high) and a 0.1 m square Lambertian emitter (1000 cd/m²) facing down
//! 1 m above the floor, 0.5 m from the mirror. Planar mirrors are exact image sources: the
//! light reaching the floor by way of the mirror is `ρ_s` times the light of the mirrored
//! emitter at `x = −0.5`, and every floor point sees that image through the mirror, so
//! `E_via(p) = π ρ_s L F_{dA(p)→image}` (Lambert's contour formula, exact). The direct part
//! is `π L F_{dA(p)→emitter}`. The floor is black, so all its light is the kernel's first
//! transport of the emitter, `E = π Σ_d (G x)`, and what exceeds the exact direct light came
//! by way of the mirror. Compared: means over four 0.5 m floor strips by distance from the
//! mirror, and the whole floor's flux.
//!
//! The uniform kernel carries the mirror's light by the emitter's image (`docs/design.md`
//! (3.10)): measured, worst strip / whole floor, K = 16 6.1e-6 / 1.3e-6, K = 64 4.0e-6 /
//! −1.7e-6. The cell-to-cell mirror block it replaced smeared the image over a cell: K = 16
//! 52 % / 3.0 %, K = 64 18.6 % / 1.35 %, K = 144 10.3 % / 0.96 %, K = 256 5.3 % / 0.24 %.
//!
//! A point luminaire in front of the mirror lights the floor as itself plus its image of
//! intensity `ρ_s I`: exact per strip from the solid angles, to round-off.

use crate::luminaire::point;
use crate::support::{arriving, build_with, material, mean_over, rectangle, scene, solve, surface};
use glam::DVec3;
use std::f64::consts::PI;
use ugo::directions::DirectionSet;
use ugo::geometry::Emission;
use ugo::geometry::{ConvexPolygon, Frame};
use ugo::kernel::sent_shares;
use ugo::luminaire::{Luminaire, LuminaireKind};
use ugo::material::MaterialModel;
use ugo::model::{Fingerprint, Model, Part};
use ugo::photometry::Distribution;
use ugo::readout::cut::Cut;
use ugo::readout::energy::EnergyBalance;
use ugo::readout::field::Field;
use ugo::readout::gather::illuminance_at;
use ugo::readout::mirrored::through_mirrors;
use ugo::scene::Scene;
use ugo::transfer::contour::point_to_polygon;
use ugo::visibility::NO_FACE;

const LUMINANCE: f64 = 1000.0;
const RHO: f64 = 0.8;
/// Floor strips by distance from the mirror, m.
/// Bounds of the relative errors of the light by way of the mirror (measured: see above).
const WORST_STRIP: f64 = 1e-4;
const FLOOR_TOTAL: f64 = 1e-4;
const STRIPS: [(f64, f64); 4] = [(0.0, 0.5), (0.5, 1.0), (1.0, 1.5), (1.5, 2.0)];

fn mirror_scene() -> Scene {
    let materials = vec![
        material("black", MaterialModel::Lambert { reflectance: 0.0, transmittance: 0.0 }),
        material("mirror", MaterialModel::Mirror { reflectance: RHO }),
    ];
    let lamp = Some(Emission::Luminance(LUMINANCE));
    let surfaces = vec![
        surface("floor", rectangle([0.0, 0.0, -1.0], [0.0, 0.0, 2.0], [2.0, 0.0, 0.0]), 0, false, None),
        surface("mirror", rectangle([0.0, 0.0, -1.0], [0.0, 1.0, 0.0], [0.0, 0.0, 2.0]), 1, false, None),
        surface("lamp", rectangle([0.45, 1.0, -0.05], [0.1, 0.0, 0.0], [0.0, 0.0, 0.1]), 0, false, lamp),
    ];
    scene(materials, surfaces, 0.1)
}

/// The downward-facing 0.1 m square centred at `(x, 1, 0)`.
fn square_at(x: f64) -> ConvexPolygon {
    let (a, b) = (x - 0.05, x + 0.05);
    let y = 1.0;
    ConvexPolygon::quad(
        DVec3::new(a, y, -0.05),
        DVec3::new(b, y, -0.05),
        DVec3::new(b, y, 0.05),
        DVec3::new(a, y, 0.05),
    )
}

/// Exact mean illuminance over each strip from a source of luminance `l` shaped `source`.
fn exact_strips(source: &ConvexPolygon, l: f64) -> Vec<f64> {
    assert!(source.normal().y < -0.999, "the source faces the floor");
    let e = |x: f64, z: f64| PI * l * point_to_polygon(DVec3::new(x, 0.0, z), DVec3::Y, source);
    STRIPS.iter().map(|&s| mean_over(s, (-1.0, 1.0), 10, e)).collect()
}

/// Mean over each strip of `π Σ_d v[i,d]` on the floor patches.
fn strip_means(model: &Model, v: &[f64]) -> Vec<f64> {
    let k = model.kernel.cells();
    let p = &model.mesh.patches;
    let floor: Vec<usize> = (0..p.len()).filter(|&i| p[i].surface == 0).collect();
    STRIPS
        .iter()
        .map(|&(a, b)| {
            let inside = floor.iter().filter(|&&i| (a..b).contains(&p[i].centroid.x));
            let (flux, area) = inside.fold((0.0, 0.0), |(f, s), &i| {
                (f + PI * v[i * k..(i + 1) * k].iter().sum::<f64>() * p[i].area, s + p[i].area)
            });
            flux / area
        })
        .collect()
}

/// Worst relative error over the strips and relative error of their total (equal areas).
fn errors(got: &[f64], exact: &[f64]) -> (f64, f64) {
    let worst = got.iter().zip(exact).map(|(g, e)| (g / e - 1.0).abs()).fold(0.0, f64::max);
    (worst, got.iter().sum::<f64>() / exact.iter().sum::<f64>() - 1.0)
}

/// (worst strip, floor total) relative errors of the light by way of the mirror with `k`
/// cells: the floor's light `π Σ_d (G x)` less the exact direct light, against the image's.
fn mirror_errors(scene: &Scene, k: usize) -> (f64, f64) {
    let model = build_with(scene, DirectionSet::hemisphere(k));
    assert_eq!(model.mirrors.len(), 1, "the mirror wall is one plane mirror");
    let x = solve(&model);
    let all = strip_means(&model, &arriving(&model, &x));
    let direct = exact_strips(&square_at(0.5), LUMINANCE);
    let via: Vec<f64> = all.iter().zip(&direct).map(|(a, d)| a - d).collect();
    let (worst, total) = errors(&via, &exact_strips(&square_at(-0.5), RHO * LUMINANCE));
    eprintln!("mirror, K = {k}: via the mirror worst strip {worst:.2e}, floor total {total:.2e}");
    (worst, total)
}

#[test]
fn floor_strips_match_the_image_source_at_any_cell_count() {
    let scene = mirror_scene();
    for k in [16, 64] {
        let (worst, total) = mirror_errors(&scene, k);
        assert!(worst < WORST_STRIP, "worst strip at K = {k}: {worst}");
        assert!(total.abs() < FLOOR_TOTAL, "floor total at K = {k}: {total}");
    }
}

/// The mirror scene lit by an isotropic point source of `INTENSITY` at `(0.5, 1, 0)` instead
/// of the emitting square, the mirror 2 m high so that every floor point sees the source's
/// image whole.
fn luminaire_scene() -> Scene {
    let materials = vec![
        material("black", MaterialModel::Lambert { reflectance: 0.0, transmittance: 0.0 }),
        material("mirror", MaterialModel::Mirror { reflectance: RHO }),
    ];
    let surfaces = vec![
        surface("floor", rectangle([0.0, 0.0, -1.0], [0.0, 0.0, 2.0], [2.0, 0.0, 0.0]), 0, false, None),
        surface("mirror", rectangle([0.0, 0.0, -1.0], [0.0, 2.0, 0.0], [0.0, 0.0, 2.0]), 1, false, None),
    ];
    let mut s = scene(materials, surfaces, 0.1);
    let bulb = Distribution::Isotropic { intensity: INTENSITY };
    s.luminaires.push(point("bulb", DVec3::new(0.5, 1.0, 0.0), DVec3::NEG_Y, bulb));
    s
}

const INTENSITY: f64 = 100.0;

#[test]
fn a_luminaire_seen_in_the_mirror_lights_the_floor_as_its_image() {
    let model = build_with(&luminaire_scene(), DirectionSet::hemisphere(64));
    assert_eq!(model.mirrors.len(), 1);
    let x = solve(&model);
    let light: Vec<f64> = arriving(&model, &x).iter().zip(&model.direct.arriving).map(|(g, d)| g + d).collect();
    let got = strip_means(&model, &light);
    let (source, image) = (DVec3::new(0.5, 1.0, 0.0), DVec3::new(-0.5, 1.0, 0.0));
    let exact: Vec<f64> = STRIPS
        .iter()
        .map(|&(a, b)| {
            let strip = ConvexPolygon::quad(
                DVec3::new(a, 0.0, -1.0),
                DVec3::new(a, 0.0, 1.0),
                DVec3::new(b, 0.0, 1.0),
                DVec3::new(b, 0.0, -1.0),
            );
            INTENSITY * (strip.solid_angle(source) + RHO * strip.solid_angle(image)) / (2.0 * (b - a))
        })
        .collect();
    let (worst, total) = errors(&got, &exact);
    eprintln!("luminaire and its image: worst strip {worst:.1e}, floor total {total:.1e}");
    assert!(worst < 1e-9 && total.abs() < 1e-9, "strips {got:?} against {exact:?}");
}

/// A point on the floor reads the light by way of the mirror from the emitter's image
/// (`readout::mirrored`), exact where the kernel's cell values would smear it.
#[test]
fn a_floor_point_reads_the_image_through_the_mirror() {
    let model = build_with(&mirror_scene(), DirectionSet::hemisphere(64));
    let field = Field::from_unknowns(&solve(&model), model.kernel.cells());
    let image = square_at(-0.5);
    let (mut worst, mut whole_worst): (f64, f64) = (0.0, 0.0);
    for x in [0.05, 0.3, 0.75, 1.4, 1.95] {
        let p = DVec3::new(x, 0.0, 0.2);
        let frame = Frame::around(DVec3::Y);
        let got = PI * through_mirrors(&model, &field, p, &frame, NO_FACE, &Cut::own(1e-4)).iter().sum::<f64>();
        let exact = PI * RHO * LUMINANCE * point_to_polygon(p, DVec3::Y, &image);
        worst = worst.max((got / exact - 1.0).abs());
        // the whole reading, as a grid point or a probe gathers it: the emitter and its image
        let read = illuminance_at(&model, &field, p, DVec3::Y);
        let whole = exact + PI * LUMINANCE * point_to_polygon(p, DVec3::Y, &square_at(0.5));
        whole_worst = whole_worst.max((read / whole - 1.0).abs());
    }
    eprintln!("floor points through the mirror: worst {worst:.1e}; the whole reading {whole_worst:.1e}");
    assert!(worst < 1e-9, "{worst}");
    assert!(whole_worst < 1e-9, "the gather does not read the mirror by its images: {whole_worst}");
}

/// A closed 2 m cube of 50 % Lambertian walls, one of them a 75 % plane mirror, lit by its
/// emitting ceiling: the images deliver exactly what the mirror reflects, so no flux
/// escapes and every patch's sent share is 1 (`kernel::sent_shares`, weighted by the cells'
/// projected solid angles: the images are balanced by patch here, their pieces and the
/// mirror's falling into different cells near the cells' edges).
#[test]
fn a_closed_room_with_a_plane_mirror_keeps_its_energy() {
    let materials = vec![
        material("wall", MaterialModel::Lambert { reflectance: 0.5, transmittance: 0.0 }),
        material("mirror", MaterialModel::Mirror { reflectance: 0.75 }),
    ];
    let lit = Some(Emission::Luminance(100.0));
    let sides = [
        ("floor", [0.0, 0.0, 0.0], [0.0, 0.0, 2.0], [2.0, 0.0, 0.0], 0, None),
        ("ceiling", [0.0, 2.0, 0.0], [2.0, 0.0, 0.0], [0.0, 0.0, 2.0], 0, lit),
        ("mirror", [0.0, 0.0, 0.0], [0.0, 2.0, 0.0], [0.0, 0.0, 2.0], 1, None),
        ("x = 2", [2.0, 0.0, 0.0], [0.0, 0.0, 2.0], [0.0, 2.0, 0.0], 0, None),
        ("z = 0", [0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [0.0, 2.0, 0.0], 0, None),
        ("z = 2", [0.0, 0.0, 2.0], [0.0, 2.0, 0.0], [2.0, 0.0, 0.0], 0, None),
    ];
    let surfaces = sides.iter().map(|&(name, o, u, v, m, e)| surface(name, rectangle(o, u, v), m, false, e)).collect();
    let model = build_with(&scene(materials, surfaces, 0.25), DirectionSet::hemisphere(16));
    assert_eq!(model.mirrors.len(), 1);
    let x = solve(&model);
    let energy = EnergyBalance::of(&model, &x, 6);
    let areas: Vec<f64> = model.mesh.patches.iter().map(|p| p.exposed).collect();
    let shares = sent_shares(&model.kernel, &areas, &model.mirrors);
    let cells = model.kernel.directions.cells();
    let per_patch =
        shares.chunks(cells.len()).map(|s| s.iter().zip(cells).map(|(s, c)| s * c.projected).sum::<f64>() / PI);
    let worst = per_patch.map(|s| (s - 1.0).abs()).fold(0.0, f64::max);
    let escaped = energy.escaped / energy.emitted;
    eprintln!("closed room with a plane mirror: escaped {escaped:.1e}, worst sent share {worst:.1e}");
    assert!(escaped.abs() < 1e-8 && worst < 1e-8, "escaped {escaped}, shares within {worst} of 1");
}

/// The uniform `G` holds `ρ_M` in its images: a saved kernel is not reused for another
/// mirror reflectance, nor once a luminaire is parallel light (its mirrors then reflect cell
/// to cell); another Lambertian reflectance only rebuilds the blocks.
#[test]
fn a_saved_kernel_follows_its_mirrors() {
    let scene = luminaire_scene();
    let changed = |edit: &dyn Fn(&mut Scene)| {
        let mut other = scene.clone();
        edit(&mut other);
        Fingerprint::of(&other).changes_from(&Fingerprint::of(&scene))
    };
    let refused = |changes: Vec<ugo::model::Change>| changes.iter().any(|c| c.part == Part::Materials);
    assert!(refused(changed(&|s| s.materials[1].model = MaterialModel::Mirror { reflectance: 0.5 })));
    let parallel = Luminaire {
        name: "sun".into(),
        kind: LuminaireKind::Parallel { direction: DVec3::NEG_Y, illuminance: 1000.0, glass: Default::default() },
    };
    assert!(refused(changed(&|s| s.luminaires.push(parallel.clone()))));
    let grey = MaterialModel::Lambert { reflectance: 0.5, transmittance: 0.0 };
    assert!(!refused(changed(&|s| s.materials[0].model = grey.clone())));
}
