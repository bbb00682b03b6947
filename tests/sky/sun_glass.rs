//! The sun's beam through a glazed opening (`src/sky/beam_glass.rs`, `docs/daylight.md`, "The
//! sun through glass") against the closed form: behind the glass, where the beam is not
//! shadowed, the sun gives `E_n cos θ τ(θ') M`, `θ` its incidence on the receiver, `θ'` on
//! the pane, `τ` from Fresnel's equations for the pane's index (computed here, apart from
//! `src/sky/glazing_fresnel.rs`) and `M` the window's maintenance factor; the flux it lands
//! is `E_n A cos θ' τ(θ') M` whatever it falls on.
//!
//! The room is CIE 171's 5.9 (black, 4 × 4 × 3 m, a 1 × 1 m roof opening) with the sun at
//! 40° due south: its beam meets the roof glass at 50° and falls on the north wall, where the
//! probe D (1.25 m high) and the wall's patches at 1–1.5 m are wholly in it, A and F not.
//! The sun's part is the difference of the solves with and without it (the field is linear
//! in its sources), on the patches, the probes and a grid.

use crate::cie171::solve_model;
use glam::DVec3;
use std::f64::consts::PI;
use std::path::Path;
use ugo::luminaire::{Light, Source, patch_lights};
use ugo::model::Model;
use ugo::progress::Silent;
use ugo::readout::field::Field;
use ugo::readout::grid::read_grids;
use ugo::readout::probe::read_probes;
use ugo::scene::Scene;

/// Illuminance normal to the beam, lx.
const SUN: f64 = 60_000.0;
/// The sun's altitude, degrees: the beam meets the horizontal glass at 90° − 40° = 50°.
const ALTITUDE: f64 = 40.0;
const INDEX: f64 = 1.52;

/// A grid of 4 × 3 points on the north wall, all in the sun patch (x 1.5–2.5 m, y 0.90–1.74 m).
const GRID: &str = "[[grid]]\nname = \"sunlit\"\norigin = [1.6, 1.0, 0.0]\nedge_u = [0.8, 0.0, 0.0]\n\
                    edge_v = [0.0, 0.6, 0.0]\nresolution = [4, 3]\n";

/// CIE 171's 5.9 with its roof glazed by `glass` (TOML keys), the sun at [`ALTITUDE`]
/// shining `sun` lx, and the sunlit grid.
fn roof(glass: &str, sun: f64) -> Scene {
    let path = Path::new("cases/cie171/5.9-roof-1x1.toml");
    let text = std::fs::read_to_string(path).unwrap();
    let sunny = format!("ground_reflectance = 0.0\nsun_illuminance = {sun}\n");
    let edits = [
        ("sun_altitude_deg = 60.0", format!("sun_altitude_deg = {ALTITUDE}")),
        ("ground_reflectance = 0.0\n", sunny),
        ("edge_v = [0.0, 0.0, 1.0]\n", format!("edge_v = [0.0, 0.0, 1.0]\n{glass}")),
    ];
    let mut text = edits.iter().fold(text, |t, (from, to)| {
        assert!(t.contains(from), "{from}");
        t.replacen(from, to, 1)
    });
    text.push_str(GRID);
    Scene::parse(path, text).unwrap_or_else(|e| panic!("{e}"))
}

/// Fresnel's reflectances of the air–glass face at incidence `cos`, (s, p).
fn fresnel(cos: f64, n: f64) -> (f64, f64) {
    let sin_t = (1.0 - cos * cos).sqrt() / n;
    let cos_t = (1.0 - sin_t * sin_t).sqrt();
    let rs = ((cos - n * cos_t) / (cos + n * cos_t)).powi(2);
    let rp = ((n * cos - cos_t) / (n * cos + cos_t)).powi(2);
    (rs, rp)
}

/// `τ` of `panes` lossless panes: `(1 − r)/(1 + (2N − 1) r)` per polarisation, averaged.
fn lossless(cos: f64, panes: u32) -> f64 {
    let (rs, rp) = fresnel(cos, INDEX);
    let one = |r: f64| (1.0 - r) / (1.0 + (2.0 * panes as f64 - 1.0) * r);
    0.5 * (one(rs) + one(rp))
}

/// `τ` of one absorbing pane of normal transmittance `normal`, by summing the beam's
/// reflections inside it (10⁴ terms; `a₀` by bisection on the normal transmittance).
fn absorbing(cos: f64, normal: f64) -> f64 {
    let slab = |r: f64, a: f64| (0..10_000).map(|k| (1.0 - r).powi(2) * a * (r * r * a * a).powi(k)).sum::<f64>();
    let r0 = ((INDEX - 1.0) / (INDEX + 1.0)).powi(2);
    let (mut lo, mut hi) = (0.0, 1.0);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if slab(r0, mid) < normal { lo = mid } else { hi = mid }
    }
    let cos_t = (1.0 - (1.0 - cos * cos) / (INDEX * INDEX)).sqrt();
    let a = lo.powf(1.0 / cos_t);
    let (rs, rp) = fresnel(cos, INDEX);
    0.5 * (slab(rs, a) + slab(rp, a))
}

/// The sun's part of every probe's, grid point's and patch's illuminance, and of the flux
/// landed (the solve with the sun less the solve without).
struct SunPart {
    probes: Vec<f64>,
    grid: Vec<f64>,
    /// The north wall's patches wholly in the sun.
    patches: Vec<f64>,
    flux: f64,
}

fn sun_part(glass: &str) -> (Scene, SunPart) {
    let read = |scene: &Scene| {
        let model = Model::build(scene, &Silent).expect("fits");
        let x = solve_model(&model, scene.solver.method);
        let field = Field::from_unknowns(&x, model.kernel.cells());
        let probes: Vec<f64> =
            read_probes(&scene.probes, &model, &field, &Silent).iter().map(|p| p.illuminance).collect();
        let grid = read_grids(&scene.grids, &model, &field, &Silent).remove(0).illuminance;
        (model, probes, grid)
    };
    let (sunny, dull) = (roof(glass, SUN), roof(glass, 0.0));
    let ((model, probes, grid), (_, probes0, grid0)) = (read(&sunny), read(&dull));
    let sun: Vec<Source> =
        model.sources.iter().filter(|s| matches!(s.light, Light::Parallel { .. })).cloned().collect();
    assert_eq!(sun.len(), 1, "the sun");
    let lights = patch_lights(&sun, &model.mesh.patches, &model.visibility, &model.kernel.directions, &[], &[]);
    let part = SunPart {
        probes: probes.iter().zip(&probes0).map(|(a, b)| a - b).collect(),
        grid: grid.iter().zip(&grid0).map(|(a, b)| a - b).collect(),
        patches: (model.mesh.patches.iter().zip(&lights))
            .filter(|(p, _)| in_the_sun(p.normal, p.polygon.centroid()))
            .map(|(_, l)| PI * l.arriving.iter().sum::<f64>())
            .collect(),
        flux: lights.iter().map(|l| l.intercepted[0]).sum(),
    };
    (sunny, part)
}

/// Checks the sun's part behind glass of transmittance `tau` at the beam's incidence and
/// maintenance factor `m` against the closed form.
fn behind_glass(glass: &str, tau: f64, m: f64) {
    let (scene, part) = sun_part(glass);
    let h = ALTITUDE.to_radians();
    let on_wall = SUN * h.cos() * tau * m; // the north wall faces the beam at 40° from its normal
    let flux = SUN * 1.0 * h.sin() * tau * m; // the 1 m² roof seen along the beam
    eprintln!("{glass:?}: τ(50°) = {tau:.6}, M = {m}: wall {on_wall:.4} lx, flux {flux:.4} lm");
    for (probe, e) in scene.probes.iter().zip(&part.probes) {
        let expected = if probe.name == "D" {
            on_wall
        } else if ["A", "F", "G"].contains(&probe.name.as_str()) {
            0.0
        } else {
            continue;
        };
        eprintln!("  probe {}: {e:.6} lx against {expected:.6}", probe.name);
        assert!((e - expected).abs() <= 1e-9 * on_wall, "probe {}: {e} against {expected}", probe.name);
    }
    for e in &part.grid {
        assert!((e / on_wall - 1.0).abs() <= 1e-9, "grid point: {e} against {on_wall}");
    }
    assert_eq!(part.patches.len(), 2, "the north wall's patches at 1–1.5 m, x 1.5–2.5 m");
    for e in &part.patches {
        assert!((e / on_wall - 1.0).abs() <= 1e-9, "patch: {e} against {on_wall}");
    }
    eprintln!("  flux landed {:.4} lm against {flux:.4} ({:+.2e})", part.flux, part.flux / flux - 1.0);
    assert!((part.flux / flux - 1.0).abs() <= 2e-3, "flux {} against {flux}", part.flux);
}

/// A patch of the north wall wholly in the sun patch (y 0.90–1.74 m, x 1.5–2.5 m): its
/// 0.5 m patches at 1–1.5 m.
fn in_the_sun(normal: DVec3, centroid: DVec3) -> bool {
    normal.z > 0.99 && centroid.z.abs() < 1e-9 && (centroid.y - 1.25).abs() < 1e-9 && (1.5..2.5).contains(&centroid.x)
}

#[test]
fn the_sun_through_one_lossless_pane_is_attenuated_by_fresnels_transmittance() {
    let normal = 2.0 * INDEX / (INDEX * INDEX + 1.0);
    let cos = (90.0 - ALTITUDE).to_radians().cos();
    behind_glass(&format!("transmittance = {normal:.17}\n"), lossless(cos, 1), 1.0);
}

#[test]
fn the_sun_through_two_lossless_panes_and_dirt_is_attenuated_by_both() {
    let normal = 2.0 * INDEX / (INDEX * INDEX + 1.0);
    let cos = (90.0 - ALTITUDE).to_radians().cos();
    behind_glass(
        &format!("transmittance = {normal:.17}\npanes = 2\nmaintenance_factor = 0.9\n"),
        lossless(cos, 2),
        0.9,
    );
}

#[test]
fn the_sun_through_an_absorbing_pane_and_dirt_is_attenuated_by_its_transmittance() {
    let cos = (90.0 - ALTITUDE).to_radians().cos();
    behind_glass("transmittance = 0.8\nmaintenance_factor = 0.8\n", absorbing(cos, 0.8), 0.8);
}

#[test]
fn the_sun_through_an_open_hole_is_not_attenuated() {
    behind_glass("", 1.0, 1.0);
}
