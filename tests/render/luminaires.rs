//! Luminaires drawn with their luminous opening: a camera looking at a panel of an IES file
//! sized 0.6 × 0.6 m reads `I(γ) / (A cos γ)`, dimmed with its light scene's factor; a
//! luminaire without an opening is a sphere of 0.1 m at `I / (π r²)`; a surface in front
//! hides it; the files' openings are read in metres; `ugo trace`'s camera sees the panel
//! and the sky as the render does; a lamp filling the view does not set the exposure.

use super::{lit_scene, solved_lamp_room};
use crate::support::{lambert, rectangle, scene, scratch, surface, ugo};
use glam::DVec3;
use std::f64::consts::PI;
use std::path::Path;
use ugo::geometry::{ConvexPolygon, Mesh, Surface};
use ugo::luminaire::{Light, Luminaire, LuminaireKind, PointLuminaire, Source, frame};
use ugo::photometry::{Distribution, FALLBACK_DIAMETER, LuminousOpening, parse_ies, read_ldt};
use ugo::random::Rng;
use ugo::render::LitScene;
use ugo::sky::{Brightness, Distribution as SkyDistribution, Opening, Sky};
use ugo::trace::{Start, TraceOptions, World, luminance_along};

/// A 0.6 × 0.6 m panel (metres, units type 2), 1000 cd at the nadir, 600 cd at 45°, none
/// at 90°, axially symmetric.
const PANEL: &str = "IESNA:LM-63-2002\n[TEST] panel\nTILT=NONE\n1 -1 1 3 1 1 2 0.6 0.6 0\n1 1 0\n\
                     0 45 90\n0\n1000 600 0\n";

fn panel(at: DVec3, distribution: Distribution) -> Source {
    let light = Light::Point { position: at, frame: frame(DVec3::NEG_Y, 0.0), distribution, scale: 1.0 };
    Source { name: "panel".into(), light, dimmed: 1.0 }
}

fn table() -> Distribution {
    Distribution::Table(Box::new(parse_ies(Path::new("panel.ies"), PANEL).expect("a valid file")))
}

fn seen(lit: &LitScene, from: DVec3, towards: DVec3) -> f64 {
    lit.luminance_along(from, (towards - from).normalize(), 0, &mut Rng::keyed(1))
}

/// A black floor far below, out of the way.
fn floor() -> Vec<Surface> {
    vec![surface("floor", rectangle([-5.0, -3.0, -5.0], [0.0, 0.0, 10.0], [10.0, 0.0, 0.0]), 0, false, None)]
}

#[test]
fn a_panel_is_seen_at_its_intensity_over_its_projected_area() {
    let at = DVec3::new(0.0, 2.8, 0.0);
    let lit = lit_scene(vec![lambert("black", 0.0)], floor(), vec![panel(at, table())]);
    let area = 0.36;
    let below = seen(&lit, DVec3::ZERO, at);
    assert!((below - 1000.0 / area).abs() < 1e-9 * below, "straight below: {below} cd/m², I/A = {}", 1000.0 / area);
    let oblique = seen(&lit, DVec3::new(-2.8, 0.0, 0.0), at);
    let expected = 600.0 / (area * 45f64.to_radians().cos());
    assert!((oblique - expected).abs() < 1e-9 * expected, "at 45°: {oblique} cd/m², I/(A cos γ) = {expected}");
    assert_eq!(seen(&lit, DVec3::ZERO, at + DVec3::new(0.35, 0.0, 0.0)), 0.0, "beside the panel");
    assert!(seen(&lit, DVec3::ZERO, at + DVec3::new(0.29, 0.0, 0.29)) > 0.0, "inside its corner");
}

#[test]
fn a_dimmed_panel_is_dimmer_a_switched_off_one_black_and_one_behind_a_surface_hidden() {
    let at = DVec3::new(0.0, 2.8, 0.0);
    let full = seen(&lit_scene(vec![lambert("black", 0.0)], floor(), vec![panel(at, table())]), DVec3::ZERO, at);
    let half = lit_scene(vec![lambert("black", 0.0)], floor(), vec![panel(at, table()).scaled(0.5)]);
    assert!((seen(&half, DVec3::ZERO, at) - 0.5 * full).abs() < 1e-9 * full);
    let off = lit_scene(vec![lambert("black", 0.0)], floor(), vec![panel(at, table()).scaled(0.0)]);
    assert_eq!(seen(&off, DVec3::ZERO, at), 0.0);
    let grey = vec![lambert("grey", 0.5)];
    // A one-sided sheet at 2 m facing down, emitting nothing: what it shows is 0 in the field.
    let mut surfaces = floor();
    surfaces.push(surface("sheet", rectangle([-1.0, 2.0, -1.0], [2.0, 0.0, 0.0], [0.0, 0.0, 2.0]), 0, false, None));
    let hidden = lit_scene(grey, surfaces, vec![panel(at, table())]);
    assert_eq!(seen(&hidden, DVec3::ZERO, at), 0.0, "the sheet is nearer");
}

#[test]
fn a_luminaire_without_an_opening_is_a_small_sphere() {
    let at = DVec3::new(0.0, 2.0, 0.0);
    let lamp = panel(at, Distribution::Isotropic { intensity: 100.0 });
    let lit = lit_scene(vec![lambert("black", 0.0)], floor(), vec![lamp]);
    let r = FALLBACK_DIAMETER / 2.0;
    let expected = 100.0 / (PI * r * r);
    for from in [DVec3::ZERO, DVec3::new(3.0, 2.0, 1.0), DVec3::new(0.0, 5.0, 0.0)] {
        let l = seen(&lit, from, at);
        assert!((l - expected).abs() < 1e-9 * expected, "from {from}: {l} cd/m², I/(πr²) = {expected}");
    }
    assert_eq!(seen(&lit, DVec3::ZERO, at + DVec3::new(1.01 * r, 0.0, 0.0)), 0.0);
}

#[test]
fn the_files_size_their_luminous_openings_in_metres() {
    let ies = parse_ies(Path::new("panel.ies"), PANEL).expect("valid");
    assert_eq!(ies.luminous, Some(LuminousOpening::Box { length: 0.6, width: 0.6, height: 0.0 }));
    let feet = PANEL.replace("1 1 2 0.6 0.6 0", "1 1 1 -2 -2 0.5");
    let round = parse_ies(Path::new("round.ies"), &feet).expect("valid");
    let Some(LuminousOpening::Cylinder { diameter, height }) = round.luminous else { panic!("{:?}", round.luminous) };
    assert!((diameter - 0.6096).abs() < 1e-12 && (height - 0.1524).abs() < 1e-12, "{diameter} {height}");
    let none = PANEL.replace("0.6 0.6 0", "0 0 0");
    assert_eq!(parse_ies(Path::new("point.ies"), &none).expect("valid").luminous, None);
    let ldt = read_ldt(Path::new("tests/data/photometry/isym4-quadrant.ldt")).expect("valid");
    assert_eq!(ldt.luminous, Some(LuminousOpening::Box { length: 0.58, width: 0.58, height: 0.0 }));
}

#[test]
fn the_traced_camera_sees_the_panel_and_the_sky_as_the_render_does_and_a_probe_neither() {
    let at = DVec3::new(0.0, 2.8, 0.0);
    let mut s = scene(vec![lambert("black", 0.0)], floor(), 0.5);
    let placed = PointLuminaire {
        position: at,
        aim: DVec3::NEG_Y,
        rotate_deg: 0.0,
        multiplier: 1.0,
        distribution: table(),
        file: None,
    };
    let sky = Sky::new(SkyDistribution::Overcast, DVec3::Y, Brightness::Zenith(1000.0), 0.2, 0.0);
    let roof = ConvexPolygon::quad(
        DVec3::new(2.0, 4.0, -2.0),
        DVec3::new(4.0, 4.0, -2.0),
        DVec3::new(4.0, 4.0, 2.0),
        DVec3::new(2.0, 4.0, 2.0),
    );
    let window = LuminaireKind::Window { window: Opening { polygon: roof, glazing: None }, sky };
    s.luminaires.push(Luminaire { name: "panel".into(), kind: LuminaireKind::Point(placed) });
    s.luminaires.push(Luminaire { name: "roof".into(), kind: window });
    let world = World::new(&s, Mesh::build(&s.surfaces, 0.5));
    let lit = lit_scene(vec![lambert("black", 0.0)], floor(), s.luminaires.iter().map(Source::of).collect());
    let options = TraceOptions::default();
    for towards in [at, DVec3::new(3.0, 4.0, 0.5)] {
        let d = towards.normalize();
        let traced = luminance_along(&world, Start::camera(DVec3::ZERO, d), &mut Rng::keyed(1), &options, &mut 0);
        let rendered = seen(&lit, DVec3::ZERO, towards);
        assert!(
            rendered > 0.0 && (traced - rendered).abs() < 1e-9 * rendered,
            "towards {towards}: {traced} {rendered}"
        );
        let probe = luminance_along(&world, Start::eye(DVec3::ZERO, d), &mut Rng::keyed(1), &options, &mut 0);
        assert_eq!(probe, 0.0, "a probe's luminance is its first surface's");
    }
}

#[test]
fn a_luminaire_filling_the_view_does_not_set_the_automatic_exposure() {
    // CIE 171's 5.4: an isotropic 10 000 lm lamp at (2, 1.5, 2), no luminous opening: a
    // sphere of 0.1 m at I/(π r²) ≈ 1.0e5 cd/m², seen from 0.3 m over about a fifth of the
    // image. The room it lights stays below 1000 cd/m²: the exposure must be the room's.
    let dir = scratch("exposure");
    let (_, h5) = solved_lamp_room(&dir);
    let view = ["--position", "2,1.5,2.3", "--look-at", "2,1.5,0", "--resolution", "32,32", "--fov-deg", "40"];
    let o = ugo(&[&["render", h5.to_str().unwrap(), "-o", dir.to_str().unwrap()][..], &view[..]].concat());
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let note = std::fs::read_to_string(dir.join("5.4-flux-conservation-cli-flat.png.txt")).unwrap();
    let number = |after: &str| -> f64 {
        let rest = &note[note.find(after).unwrap_or_else(|| panic!("{after} in {note}")) + after.len()..];
        rest.split_whitespace().next().unwrap().parse().unwrap()
    };
    let lamp = 10_000.0 / (4.0 * PI) / (PI * 0.05 * 0.05);
    assert!((number(" .. ") / lamp - 1.0).abs() < 1e-6, "the lamp is seen: {note}");
    assert!(number("exposure (white) ") < 1000.0, "the room sets the exposure: {note}");
}
