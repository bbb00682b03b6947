//! 5.9 to 5.14: the sky component and the externally reflected component through openings
//! in a black room, open or (5.10, 5.12) glazed with CIE 171's 6 mm clear glass, for the 15
//! CIE standard general skies and the CIE traditional overcast sky (the 16th column),
//! against CIE 171's Appendix B (`tests/data/cie171/`). Each case is built once; each sky
//! column puts its sky in the model's openings, and each table its glazing (so the large
//! glazed openings are read on the open case's model: its build takes a minute, and the
//! glazed case files are checked to be the open ones under glass). A point off by more
//! than 1 % must be a listed deviation
//! (`tests/data/cie171/deviations.txt`, with the value ugo computed, which it must still
//! give to 0.1 %), and there ugo must agree within 0.3 % (+ 0.002) with a brute-force integral over
//! the opening's area written out here (2-D midpoint rule, a ray per sample, traced once per
//! point and reused for every sky and glass).
//! Run with `--nocapture` for the rows of `docs/validation-daylight.md`.

use super::{TOLERANCE, solve_model};
use glam::DVec3;
use std::path::Path;
use ugo::luminaire::{Light, LuminaireKind};
use ugo::model::Model;
use ugo::progress::Silent;
use ugo::readout::field::Field;
use ugo::readout::openings::sky_and_ground;
use ugo::readout::probe::read_probes;
use ugo::scene::Scene;
use ugo::sky::{Brightness, Distribution, Glazing, Opening, Sky};

/// CIE 171's glazed cases: their tables are read through its 6 mm clear glass.
const GLAZED: [&str; 2] = ["5.10", "5.12"];

/// The listed deviations: `(table file, sky type, point)` and the value ugo computes there.
fn deviations() -> Vec<((String, u8, String), f64)> {
    let text = std::fs::read_to_string("tests/data/cie171/deviations.txt").expect("the deviations");
    text.lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
        .map(|l| {
            let w: Vec<&str> = l.split_whitespace().collect();
            ((w[0].to_string(), w[1].parse().expect("a type"), w[2].to_string()), w[4].parse().expect("ugo"))
        })
        .collect()
}

/// A table: its point names and, per sky type, the values.
struct Table {
    points: Vec<String>,
    rows: Vec<(u8, Vec<f64>)>,
}

fn table(file: &str) -> Table {
    let text = std::fs::read_to_string(Path::new("tests/data/cie171").join(file)).expect("the table");
    let mut lines = text.lines().filter(|l| !l.starts_with('#'));
    let points = lines.next().expect("a header").split_whitespace().skip(1).map(str::to_string).collect();
    let rows = lines
        .map(|l| {
            let mut words = l.split_whitespace();
            let t = words.next().and_then(|w| w.parse().ok()).expect("a sky type");
            (t, words.map(|w| w.parse().expect("a number")).collect())
        })
        .collect();
    Table { points, rows }
}

fn distribution(t: u8) -> Distribution {
    if t == 16 { Distribution::Overcast } else { Distribution::General(t) }
}

/// The model's openings under sky type `t` (the case's sun, brightness and ground).
fn with_sky(model: &mut Model, t: u8) {
    for source in &mut model.sources {
        if let Light::Window { sky, .. } = &mut source.light {
            let brightness = Brightness::Horizontal(sky.horizontal_illuminance);
            *sky = Sky::new(distribution(t), sky.sun, brightness, sky.ground_reflectance, sky.sun_horizontal);
        }
    }
}

/// The glass of the openings a table `file` is read through.
fn glazing_of(file: &str) -> Option<Glazing> {
    GLAZED.iter().any(|case| file.starts_with(case)).then_some(Glazing::Cie171)
}

/// The model's openings glazed with `glazing` (`None`: open).
fn with_glazing(model: &mut Model, glazing: Option<Glazing>) {
    for source in &mut model.sources {
        if let Light::Window { window, .. } = &mut source.light {
            window.glazing = glazing;
        }
    }
}

/// `E_h` of the openings' sky, lx.
fn horizontal_illuminance(model: &Model) -> f64 {
    let e_h = model.sources.iter().find_map(|s| match &s.light {
        Light::Window { sky, .. } => Some(sky.horizontal_illuminance),
        _ => None,
    });
    e_h.expect("an opening")
}

/// `100 E / E_h` at a probe of the black room: the sky and ground through the openings.
fn percent(model: &Model, p: DVec3, n: DVec3) -> f64 {
    let (sc, erc) = sky_and_ground(model, p, n);
    100.0 * (sc + erc) / horizontal_illuminance(model)
}

/// Samples of the brute-force sum: an `m × m` grid of midpoints over every opening.
const M: usize = 600;

/// The midpoints of every opening's grid: the point, its area, the opening and its sky.
fn midpoints(model: &Model) -> impl Iterator<Item = (DVec3, f64, &Opening, &Sky)> {
    model
        .sources
        .iter()
        .filter_map(|s| match &s.light {
            Light::Window { window, sky } => Some((window, sky)),
            _ => None,
        })
        .flat_map(|(window, sky)| {
            let v = window.polygon.vertices();
            let (o, u, w) = (v[0], v[1] - v[0], v[3] - v[0]);
            let da = u.cross(w).length() / (M * M) as f64;
            (0..M * M).map(move |k| {
                let (i, j) = ((k / M) as f64 + 0.5, (k % M) as f64 + 0.5);
                (o + u * (i / M as f64) + w * (j / M as f64), da, window, sky)
            })
        })
}

/// Which midpoints `p` (facing `n`) sees, one ray each: traced once per point, whatever
/// the sky and the glass.
fn seen_from(model: &Model, p: DVec3, n: DVec3) -> Vec<bool> {
    midpoints(model)
        .map(|(x, ..)| (x - p).dot(n) > 0.0 && model.visibility.closest_hit(p, x - p, u32::MAX).is_none())
        .collect()
}

/// `100 E / E_h` by the midpoint sum over the midpoints `seen` from `p` (facing `n`).
fn brute_force(model: &Model, p: DVec3, n: DVec3, seen: &[bool]) -> f64 {
    let e: f64 = midpoints(model)
        .zip(seen)
        .filter(|(_, seen)| **seen)
        .map(|((x, da, window, sky), _)| {
            let (r, l) = (x - p, (x - p).normalize());
            let cos_opening = l.dot(window.polygon.normal()).abs();
            let glass = window.glazing.map_or(1.0, |g| g.transmittance(cos_opening));
            glass * sky.luminance(l) * l.dot(n) * cos_opening / r.length_squared() * da
        })
        .sum();
    100.0 * e / horizontal_illuminance(model)
}

fn load(case: &str) -> Scene {
    Scene::load(&Path::new("cases/cie171").join(format!("{case}.toml"))).unwrap_or_else(|e| panic!("{e}"))
}

/// Loads `cases/cie171/<case>.toml`, builds it, and checks every sky column of `files`,
/// each through its glass ([`glazing_of`]); returns what is wrong.
fn check(case: &str, files: &[&str]) -> Vec<String> {
    let listed = deviations();
    let scene = load(case);
    let mut model = Model::build(&scene, &ugo::progress::Silent).expect("fits");
    // The case's own sky (overcast) through the whole solve: the black room's probes read
    // exactly the sky and ground through the openings.
    let x = solve_model(&model, scene.solver.method);
    let probes = read_probes(&scene.probes, &model, &Field::from_unknowns(&x, model.kernel.cells()), &Silent);
    for r in &probes {
        let direct = percent(&model, r.position, r.normal);
        assert!((100.0 * r.illuminance / 10_000.0 - direct).abs() < 1e-9, "{case} {}: solved", r.name);
    }
    let mut failures = Vec::new();
    // The midpoints each probe sees, traced when first needed.
    let mut seen: Vec<(String, Vec<bool>)> = Vec::new();
    for file in files {
        let t = table(file);
        with_glazing(&mut model, glazing_of(file));
        for (sky, values) in &t.rows {
            let types: Vec<u8> = if *sky == 0 { (1..=16).collect() } else { vec![*sky] };
            for &ty in &types {
                with_sky(&mut model, ty);
                for (name, &reference) in t.points.iter().zip(values) {
                    let probe = scene.probes.iter().find(|p| &p.name == name).expect("the probe");
                    let ugo = percent(&model, probe.position, probe.normal);
                    let off = ugo / reference - 1.0;
                    let key = (file.to_string(), ty, name.clone());
                    let recorded = listed.iter().find(|(k, _)| *k == key).map(|(_, v)| *v);
                    let mark = match (off.abs() > TOLERANCE, recorded) {
                        (true, Some(_)) => " (deviation)",
                        (true, None) => " FAIL",
                        _ => "",
                    };
                    eprintln!(
                        "| {case} | {file} | {ty} | {name} | {reference} | {ugo:.3} | {:+.2} %{mark} |",
                        100.0 * off
                    );
                    if off.abs() > TOLERANCE || recorded.is_some() {
                        if !seen.iter().any(|(n, _)| n == name) {
                            seen.push((name.clone(), seen_from(&model, probe.position, probe.normal)));
                        }
                        let (_, samples) = seen.iter().find(|(n, _)| n == name).expect("traced");
                        let brute = brute_force(&model, probe.position, probe.normal, samples);
                        // Relative, and absolute (in % of E_h) where a shadow hides nearly all.
                        let agrees = (ugo - brute).abs() <= 3e-3 * brute + 2e-3;
                        let same = recorded.is_some_and(|v| (ugo - v).abs() <= 1e-3 * v + 1e-4);
                        if !same || !agrees {
                            eprintln!("DEVIATION {file} {ty} {name} {reference} {ugo:.4} {brute:.4}");
                            failures.push(format!(
                                "{file} type {ty} {name}: CIE {reference}, ugo {ugo:.4}, brute {brute:.4}"
                            ));
                        }
                    }
                }
            }
            if *sky == 0 {
                break;
            }
        }
    }
    failures
}

fn assert_none(failures: Vec<String>) {
    assert!(failures.is_empty(), "{} points:\n{}", failures.len(), failures.join("\n"));
}

/// The open case and its glazed twin.
const TWINS: [(&str, &str); 4] = [
    ("5.9-roof-1x1", "5.10-roof-1x1"),
    ("5.9-roof-4x4", "5.10-roof-4x4"),
    ("5.11-facade-2x1", "5.12-facade-2x1"),
    ("5.11-facade-4x3", "5.12-facade-4x3"),
];

#[test]
fn the_glazed_cases_are_the_open_ones_under_cie_171_glass() {
    for (open, glazed) in TWINS {
        let (o, g) = (load(open), load(glazed));
        assert_eq!(format!("{:?}", o.surfaces), format!("{:?}", g.surfaces), "{glazed}");
        assert_eq!(o.probes, g.probes, "{glazed}");
        assert_eq!(o.sky, g.sky, "{glazed}");
        assert_eq!(o.luminaires.len(), g.luminaires.len(), "{glazed}");
        for (a, b) in o.luminaires.iter().zip(&g.luminaires) {
            let (LuminaireKind::Window { window: a, sky: s }, LuminaireKind::Window { window: b, sky: t }) =
                (&a.kind, &b.kind)
            else {
                panic!("{glazed}: only openings")
            };
            assert_eq!((a.polygon, s, a.glazing), (b.polygon, t, None), "{glazed}");
            assert_eq!(b.glazing, Some(Glazing::Cie171), "{glazed}");
        }
    }
}

#[test]
fn cie_5_9_roof_openings_and_the_glazed_4x4_of_5_10() {
    let mut failures = check("5.9-roof-1x1", &["5.9-1x1.txt"]);
    failures.extend(check("5.9-roof-4x4", &["5.9-4x4.txt", "5.10-4x4.txt"]));
    assert_none(failures);
}

#[test]
fn cie_5_10_glazed_1x1_roof_opening() {
    assert_none(check("5.10-roof-1x1", &["5.10-1x1.txt"]));
}

#[test]
fn cie_5_11_facade_openings_and_the_glazed_4x3_of_5_12() {
    let mut failures = check("5.11-facade-2x1", &["5.11-2x1.txt", "5.11-2x1-ceiling.txt"]);
    let tables = ["5.11-4x3.txt", "5.11-4x3-ceiling.txt", "5.12-4x3.txt", "5.12-4x3-ceiling.txt"];
    failures.extend(check("5.11-facade-4x3", &tables));
    assert_none(failures);
}

#[test]
fn cie_5_12_glazed_2x1_facade_opening() {
    assert_none(check("5.12-facade-2x1", &["5.12-2x1.txt", "5.12-2x1-ceiling.txt"]));
}

#[test]
fn cie_5_13_under_a_horizontal_mask() {
    let failures = ["0.5", "1.0", "2.0"]
        .iter()
        .flat_map(|depth| check(&format!("5.13-overhang-{depth}"), &[&format!("5.13-{depth}.txt")]))
        .collect();
    assert_none(failures);
}

#[test]
fn cie_5_14_facing_a_vertical_mask() {
    let failures = ["3", "6", "9"]
        .iter()
        .flat_map(|height| check(&format!("5.14-facing-wall-{height}"), &[&format!("5.14-{height}.txt")]))
        .collect();
    assert_none(failures);
}
