//! The fast subset of the hard-probe benchmark (issue 34, point 1; docs/accuracy.md): the
//! Cornell box, the open box, the slot behind a desk, the whiteboard and the seats on
//! tiers at their case's settings, read at
//! their committed hard probes (tests/data/accuracy/CASE.csv, `ugo trace` references at about 0.3 % standard
//! error, made by tools/accuracy/bench.py), each class's largest error held to today's
//! figure rounded up, so that a regression fails. These bounds are not the goal: the
//! issue's target is every hard probe within 1 % of its reference (mean ≤ 0.3 %).

mod error_bars;
mod glossy;
mod grid_error_bars;
mod one_ray_pieces;

use crate::support::{build, solve};
use glam::DVec3;
use std::collections::BTreeMap;
use std::path::Path;
use std::sync::OnceLock;
use ugo::model::Model;
use ugo::progress::Silent;
use ugo::readout::field::Field;
use ugo::readout::probe::{ProbeReading, read_probes};
use ugo::scene::{KernelKind, Probe, Scene};

/// A committed reference: each probe with its class, illuminance and standard error, lx.
struct Reference {
    probes: Vec<Probe>,
    class: Vec<String>,
    illuminance: Vec<f64>,
}

/// Reads tests/data/accuracy/`name`.csv.
fn reference(name: &str) -> Reference {
    let path = Path::new("tests/data/accuracy").join(format!("{name}.csv"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let mut rows = text.lines().filter(|l| !l.starts_with('#'));
    let header: Vec<&str> = rows.next().expect("a header").split(',').collect();
    let column = |key: &str| header.iter().position(|h| *h == key).unwrap_or_else(|| panic!("no column {key}"));
    let (name_at, class_at, x_at, n_at, e_at) =
        (column("name"), column("class"), column("x"), column("nx"), column("E_lx"));
    let mut out = Reference { probes: Vec::new(), class: Vec::new(), illuminance: Vec::new() };
    for row in rows {
        let f: Vec<&str> = row.split(',').collect();
        let number = |i: usize| f[i].parse::<f64>().unwrap_or_else(|e| panic!("{row}: {e}"));
        let vector = |i: usize| DVec3::new(number(i), number(i + 1), number(i + 2));
        out.probes.push(Probe::point(f[name_at], vector(x_at), vector(n_at).normalize()));
        out.class.push(f[class_at].to_string());
        out.illuminance.push(number(e_at));
    }
    out
}

/// The case with the reference's probes in place of its own.
fn bench_scene(case: &str, reference: &Reference) -> Scene {
    let mut scene = Scene::load(&Path::new("cases").join(format!("{case}.toml"))).unwrap_or_else(|e| panic!("{e}"));
    scene.probes = reference.probes.clone();
    scene
}

/// The readings of `scene`'s probes, solved.
fn read(scene: &Scene) -> Vec<ProbeReading> {
    let model = build(scene);
    let x = solve(&model);
    read_probes(&scene.probes, &model, &Field::from_unknowns(&x, model.kernel.cells()), &Silent)
}

/// A case solved at its own settings and read at its reference's probes.
struct Solved {
    reference: Reference,
    model: Model,
    field: Field,
    readings: Vec<ProbeReading>,
}

/// `case` solved once for every test of this file: "cornell-box", "open-box", "slot-room",
/// "board-room" or "seat-room".
fn solved(case: &str) -> &'static Solved {
    static CORNELL_BOX: OnceLock<Solved> = OnceLock::new();
    static OPEN_BOX: OnceLock<Solved> = OnceLock::new();
    static SLOT_ROOM: OnceLock<Solved> = OnceLock::new();
    static BOARD_ROOM: OnceLock<Solved> = OnceLock::new();
    static SEAT_ROOM: OnceLock<Solved> = OnceLock::new();
    let once = match case {
        "cornell-box" => &CORNELL_BOX,
        "open-box" => &OPEN_BOX,
        "slot-room" => &SLOT_ROOM,
        "board-room" => &BOARD_ROOM,
        "seat-room" => &SEAT_ROOM,
        _ => panic!("no benchmark case {case}"),
    };
    once.get_or_init(|| {
        let reference = reference(case);
        let scene = bench_scene(case, &reference);
        let model = build(&scene);
        let field = Field::from_unknowns(&solve(&model), model.kernel.cells());
        let readings = read_probes(&scene.probes, &model, &field, &Silent);
        Solved { reference, model, field, readings }
    })
}

/// The largest |relative error| (%) of each class, the case solved at its own settings.
fn largest_errors(case: &str) -> BTreeMap<String, f64> {
    let Solved { reference, readings, .. } = solved(case);
    let mut largest = BTreeMap::new();
    for ((reading, class), e) in readings.iter().zip(&reference.class).zip(&reference.illuminance) {
        let error = 100.0 * (reading.illuminance / e - 1.0).abs();
        let worst = largest.entry(class.clone()).or_insert(0.0_f64);
        *worst = worst.max(error);
    }
    largest
}

/// Each class's largest error within its bound (%), every class of the bounds present.
fn check(case: &str, bounds: &[(&str, f64)]) {
    let largest = largest_errors(case);
    eprintln!("{case}: largest error by class, %: {largest:.2?}");
    let beyond: Vec<String> = bounds
        .iter()
        .filter(|(class, bound)| largest.get(*class).is_none_or(|e| e > bound))
        .map(|(class, bound)| format!("{class}: {:.2?} % > {bound} %", largest.get(*class)))
        .collect();
    assert!(beyond.is_empty(), "{case}: classes beyond today's bounds: {beyond:?}");
}

#[test]
fn the_cornell_box_at_its_hard_probes_is_no_worse_than_today() {
    // The case's uniform kernel at 0.03 m (docs/accuracy.md, "cornell-box, case"), the
    // probes corrected near geometry (docs/design.md (5.4); before it the 1 cm contacts
    // read up to 14.1 % off, the dimmest 5.5 %, the 3 cm contacts 2.5 %).
    let bounds = [
        ("corner-2cm", 0.7),
        ("corner-5cm", 0.8),
        ("corner-10cm", 1.0),
        ("edge-2cm", 0.5),
        ("edge-5cm", 1.0),
        ("edge-10cm", 0.7),
        ("contact-1cm", 1.2),
        ("contact-3cm", 3.1),
        ("umbra", 0.6),
        ("penumbra", 0.8),
        ("dim", 2.5),
        ("open", 1.3),
    ];
    check("cornell-box", &bounds);
}

#[test]
fn the_open_box_at_its_hard_probes_is_no_worse_than_today() {
    // The case's hierarchy from roots of 0.25 m. Before the emitter's leaves were balanced to
    // their columns every class read high, the open probes up to +3.8 % (the bias of issue 34,
    // docs/hierarchy.md, "An open box at coarse roots"); since, the open probes are within
    // 0.51 % and the bounds below are the fixed figures (docs/accuracy.md, "open-box, case").
    // The probes are corrected near geometry (docs/design.md (5.4)): the 1 cm contacts from
    // 25.3 to 7.0 %, the dimmest from 19.7 to 11.2 %; umbrae and corners at 5 and 10 cm are
    // the hierarchy's leaves, which the correction does not change. The push by bundles
    // (docs/hierarchy.md, "The push by bundles") moved the 1 cm contacts from 7.0 to 6.3 %,
    // the 3 cm ones from 5.6 to 4.7 %, the dimmest from 11.2 to 8.3 %, the umbrae from 3.9 to
    // 3.4 %, the 10 cm edges from 1.2 to 0.8 %, and the corners at 5 cm the other way, from
    // 2.2 to 3.0 %. Sending factors held within 1 ± 3 tolerances (docs/hierarchy.md,
    // "Sending factors held to the links' error") took every class down: the dimmest from 8.3
    // to 5.2 %, the 1 cm contacts from 6.3 to 3.6 %, the umbrae from 3.4 to 2.3 %, the corners
    // at 5 cm from 3.0 to 1.4 %; 101 of 240 probes beyond 1 % to 47. Dim receivers' own
    // allowance (docs/hierarchy.md, "Dim receivers' own allowance") took the dimmest from 5.2
    // to 2.7 %, the 1 cm contacts from 3.6 to 2.2 %, the 3 cm ones from 3.1 to 2.4 %, the
    // umbrae from 2.3 to 2.0 %; the corners at 2 cm the other way, from 0.8 to 0.9 %; 47
    // probes beyond 1 % to 31. The readings' importance (docs/hierarchy.md, "The readings'
    // importance": links refined where the 240 probes depend on them) took the dimmest from
    // 2.7 to 1.3 %, the 1 cm contacts from 2.2 to 1.4 %, the 3 cm ones from 2.4 to 1.3 %, the
    // umbrae from 2.0 to 1.5 %; the corners at 2 cm from 0.9 to 1.1 %; 31 probes beyond 1 % to 14.
    // The readings' weight chosen on a probe set of its own (κ 30 → 200, docs/hierarchy.md,
    // "The readings' weight, chosen apart") took the 1 cm contacts from 1.4 to 0.9 %, the 3 cm
    // ones from 1.3 to 0.8 %, the umbrae from 1.5 to 0.9 %, the dimmest from 1.3 to 1.0 %, the
    // corners at 10 cm from 0.9 to 0.5 %; 14 probes beyond 1 % to 2 (both at one corner point).
    // Occluded cluster pairs refined, not dropped (docs/hierarchy.md, "Occluded cluster
    // links": the office's hard probes beyond 1 % from 77 to 63) moved most classes up by a
    // few hundredths: the corners at 2 cm from 1.09 to 1.11 %, at 5 cm from 0.42 to 0.53 %,
    // the 1 cm contacts from 0.92 to 1.00 %, the umbrae from 0.87 to 0.90 %, the dimmest the
    // other way, from 0.99 to 0.95 %. The room's concave edges graded (docs/hierarchy.md,
    // "Concave edges of the room": the office's hard probes beyond 1 % from 47 to 27) took
    // one probe of the edges at 2 cm, on the dark right wall 2 cm above the floor where a
    // block's penumbra crosses it, from -0.26 to -1.18 % (-0.20 % with that one edge not
    // graded); the class's mean is 0.24 % (0.18 % without that edge), the open box's 0.31 → 0.29 %.
    // A bundle per source, each leaf by its own view (docs/hierarchy.md, "A bundle per
    // source") read these probes, which steer the links they depend on, a little worse where
    // they had steered the old push to them: the 3 cm contacts 0.8 → 1.15 %, the dimmest
    // 0.95 → 1.17 %; read on a field they did not steer (`bench.py --step unsteered
    // open-box`), better: 34 of 240 beyond 1 % → 15, mean 0.48 → 0.36 %, largest 2.40 → 1.78 %.
    // Occluded pairs tested by random segments before they are dropped (docs/hierarchy.md,
    // "Occluded pairs tested by random segments": the lecture hall's hard probes beyond 1 %
    // from 73 to 45) read these a little worse: the corners at 5 cm 0.6 → 0.70 %, at 10 cm
    // 0.6 → 0.66 %, the 5 cm edges 0.9 → 0.95 %, the 1 cm contacts 1.1 → 1.24 %, the 3 cm
    // ones 1.3 → 1.33 %, the umbrae 1.0 → 1.03 %, the penumbrae 0.6 → 0.61 %, the dimmest
    // 1.3 → 1.52 % (the figures before are the bounds they were set to).
    let bounds = [
        ("corner-2cm", 1.2),
        ("corner-5cm", 0.75),
        ("corner-10cm", 0.7),
        ("edge-2cm", 1.2),
        ("edge-5cm", 1.0),
        ("edge-10cm", 0.5),
        ("contact-1cm", 1.3),
        ("contact-3cm", 1.4),
        ("umbra", 1.1),
        ("penumbra", 0.7),
        ("dim", 1.6),
        ("open", 0.7),
    ];
    check("open-box", &bounds);
}

#[test]
fn the_correction_near_geometry_brings_contacts_closer_to_monte_carlo() {
    // The open box on a uniform 0.1 m mesh, read at the 40 contact probes of its reference
    // (1 and 3 cm from the feet of its blocks, where the floor's and the blocks' 10 cm
    // patches lie closer than their size): the readings corrected near geometry
    // (docs/design.md (5.4)) against the same readings without the correction (the
    // correction subtracted). Measured: mean |error| 3.64 % → 1.03 %, largest 24.8 % → 3.0 %.
    let reference = reference("open-box");
    let mut scene = bench_scene("open-box", &reference);
    scene.discretization.kernel = KernelKind::Uniform;
    scene.discretization.patch_size = 0.1;
    let read = read(&scene);
    let (mut plain, mut corrected) = (Vec::new(), Vec::new());
    for ((reading, class), e) in read.iter().zip(&reference.class).zip(&reference.illuminance) {
        if class.starts_with("contact") {
            plain.push(100.0 * ((reading.illuminance - reading.correction) / e - 1.0).abs());
            corrected.push(100.0 * (reading.illuminance / e - 1.0).abs());
        }
    }
    let mean = |v: &[f64]| v.iter().sum::<f64>() / v.len() as f64;
    let largest = |v: &[f64]| v.iter().fold(0.0_f64, |a, &b| a.max(b));
    eprintln!(
        "open box, uniform 0.1 m, {} contact probes: mean |error| {:.2} % → {:.2} %, largest {:.2} % → {:.2} %",
        plain.len(),
        mean(&plain),
        mean(&corrected),
        largest(&plain),
        largest(&corrected)
    );
    assert_eq!(plain.len(), 40);
    assert!(mean(&corrected) < 0.5 * mean(&plain), "the correction does not halve the mean error");
    assert!(largest(&corrected) < 0.5 * largest(&plain), "the correction does not halve the largest error");
}

#[test]
fn the_slot_behind_a_desk_is_no_worse_than_today() {
    // The office's worst probes (+6 … +8 %: the wall behind its desks' modesty panels) in a
    // 4 × 3 m room at the office's settings (docs/accuracy.md, "A slot behind a desk"):
    // the slot's probes read up to 13.6 % bright (neither tighter links, finer leaves nor
    // the uniform kernel cured it) until elements were cut along the lines of the desk's
    // edges (`kernel/hierarchy/cuts.rs`): 5.9 % since, at the panel's bottom edge; the
    // controls within 0.4 %. A bundle per source (docs/hierarchy.md): the slot 5.5 %, the
    // controls 0.53 %.
    check("slot-room", &[("slot", 6.0), ("open", 0.6)]);
}

#[test]
fn the_wall_under_a_whiteboard_is_no_worse_than_today() {
    // The office's contact-1cm/005 (+3.7 %: the wall 1 cm under its whiteboard) in a 4 × 3 m
    // room at the office's settings (docs/accuracy.md, "A whiteboard on a wall"): the board's
    // 2 cm underside read the wall's leaf under it at its mean, +27.5 % against the forward
    // bins, until the wall was graded toward it (`kernel/hierarchy/edges.rs`,
    // `graded_toward`, down to the board's width): the contacts +3.7 % before, 0.63 % since;
    // the controls 0.24 %. A bundle per source (docs/hierarchy.md): the contacts 0.21 %, the
    // underside 0.69 → 0.92 %.
    check("board-room", &[("contact", 0.8), ("underside", 1.0), ("open", 0.4)]);
}

#[test]
fn the_seats_on_tiers_are_no_worse_than_today() {
    // Two tiers of the lecture hall's seats in a 3 × 4.5 m room at the hall's settings
    // (docs/accuracy.md, "Seats on tiers"): the hall's undersides and umbrae read dark, its
    // ceiling corners bright, and so do these (relative to the probe's own illuminance: the
    // umbrae and dimmest places are 5–60 lx). Leaf by leaf the floor under the seat pans reads
    // +23 % and the riser behind them +24 % against the forward bins (docs/hierarchy.md,
    // "Clear links pushed into umbrae"). A bundle per source, each leaf by its own view
    // (docs/hierarchy.md, "A bundle per source"; the leaves against the forward bins 2.72 →
    // 1.07 % L2 beyond noise): the corners at 2 cm 2.2 → 1.85 %, the 3 cm contacts 2.1 →
    // 1.54 %, the undersides 3.6 → 2.10 %, the umbrae 6.7 → 4.35 %, the dimmest 5.7 → 4.37 %,
    // the open probes 0.6 → 0.44 % (the figures before are the bounds they were set to).
    // Occluded pairs tested by random segments (docs/hierarchy.md, "Occluded pairs tested by
    // random segments"): the corners at 2 cm 2.0 → 1.76 %, the 3 cm contacts 1.7 → 1.33 %,
    // the undersides 2.3 → 1.72 %, the umbrae 4.6 → 3.53 %, the dimmest 4.6 → 4.56 %, the
    // open probes 0.5 → 0.53 %.
    check(
        "seat-room",
        &[("corner-2cm", 1.8), ("contact-3cm", 1.4), ("underside", 1.8), ("umbra", 3.6), ("dim", 4.6), ("open", 0.6)],
    );
}

#[test]
fn leaf_row_splits_a_leafs_light_by_bundle_from_the_saved_operator() {
    // tools/accuracy/leaf_row.py (docs/hierarchy.md, "Clear links pushed into umbrae"): the
    // saved factors reproduce the solved field, and the light it lists bundle by bundle for
    // the floor under a seat pan adds up to the leaf's illuminance less its direct light.
    let dir = crate::support::scratch("leaf-row");
    let out = dir.join("seat-room.h5");
    let o = crate::support::ugo(&["solve", "cases/seat-room.toml", "--save-kernel", "-o", out.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let python = std::process::Command::new("/usr/bin/python3")
        .args(["tools/accuracy/leaf_row.py", out.to_str().unwrap(), "--at", "2.46", "0.3", "2.28", "0", "1", "0"])
        .output()
        .expect("/usr/bin/python3 runs (make deps installs python3-h5py and python3-scipy)");
    let said = String::from_utf8_lossy(&python.stdout).into_owned();
    assert!(python.status.success(), "{said}{}", String::from_utf8_lossy(&python.stderr));
    let number_after = |line: &str, key: &str| -> f64 {
        let rest = &line[line.find(key).unwrap_or_else(|| panic!("no {key} in {line}")) + key.len()..];
        rest.trim_start().split(' ').next().unwrap().trim_end_matches(',').parse().unwrap()
    };
    let leaf = said.lines().find(|l| l.starts_with("leaf ")).expect("the leaf's line");
    let (e, direct) = (number_after(leaf, ": E"), number_after(leaf, "direct"));
    let bundles: f64 =
        said.lines().filter(|l| l.trim_start().starts_with("bundle")).map(|l| number_after(l, "→")).sum();
    assert!(
        e > 0.0 && (bundles - (e - direct)).abs() <= 1e-3 * e,
        "{bundles} lx by bundle, E {e} − direct {direct}: {said}"
    );
}
