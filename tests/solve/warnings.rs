//! Physics warnings (issue 18, item 4): the field is solved, but a scene that loses its
//! light on the backs of surfaces, a luminaire inside a box, a probe facing into the floor,
//! a negative escaped flux or a mirror reflected cell to cell (not by images) is reported,
//! each naming what is wrong.

use std::path::Path;
use ugo::io::{Solution, Warning};
use ugo::kernel::{closure_shares, sent_shares};
use ugo::scene::Scene;
use ugo::study::{Job, physics_warnings, solve_case};

/// A closed unit room of six inward rectangles, a 1000 lm lamp in the middle, `extra` after;
/// uniform patches of 0.25 m (named: the size rule would take the hierarchy at that size).
fn room(floor_flipped: bool, extra: &str) -> String {
    let floor =
        if floor_flipped { "edge_u = [1, 0, 0]\nedge_v = [0, 0, 1]" } else { "edge_u = [0, 0, 1]\nedge_v = [1, 0, 0]" };
    let mut text = String::from(
        "[discretization]\npatch_size = 0.25\nkernel = \"uniform\"\n[[material]]\nname = \"grey\"\ntype = \"lambert\"\nreflectance = 0.5\n",
    );
    for (name, keys) in [
        ("floor", format!("origin = [0, 0, 0]\n{floor}")),
        ("ceiling", "origin = [0, 1, 0]\nedge_u = [1, 0, 0]\nedge_v = [0, 0, 1]".into()),
        ("west", "origin = [0, 0, 0]\nedge_u = [0, 1, 0]\nedge_v = [0, 0, 1]".into()),
        ("east", "origin = [1, 0, 0]\nedge_u = [0, 0, 1]\nedge_v = [0, 1, 0]".into()),
        ("south", "origin = [0, 0, 0]\nedge_u = [1, 0, 0]\nedge_v = [0, 1, 0]".into()),
        ("north", "origin = [0, 0, 1]\nedge_u = [0, 1, 0]\nedge_v = [1, 0, 0]".into()),
    ] {
        text += &format!("[[surface]]\nname = \"{name}\"\nshape = \"rectangle\"\nmaterial = \"grey\"\n{keys}\n");
    }
    text += "[[luminaire]]\nname = \"lamp\"\ntype = \"isotropic\"\nposition = [0.5, 0.5, 0.5]\nflux = 1000\n";
    text + extra
}

/// The warnings as they are printed and written.
fn texts(warnings: &[Warning]) -> Vec<String> {
    warnings.iter().map(ToString::to_string).collect()
}

fn solved(text: &str) -> (Scene, Solution) {
    let scene = Scene::parse(Path::new("cases/test.toml"), text.to_string()).unwrap_or_else(|e| panic!("{e}"));
    let s = solve_case(&scene, &Job::default(), &ugo::progress::Silent).unwrap();
    (scene, s)
}

#[test]
fn a_closed_room_gives_no_warning() {
    let probe = "[[probe]]\nname = \"desk\"\nposition = [0.5, 0, 0.5]\nnormal = [0, 1, 0]\n";
    let (_, s) = solved(&room(false, probe));
    assert!(s.warnings.is_empty(), "{:?}", s.warnings);
}

#[test]
fn light_lost_on_a_floor_facing_the_wrong_way_names_the_floor() {
    let (_, s) = solved(&room(true, ""));
    let warnings = texts(&s.warnings);
    let w = warnings.iter().find(|w| w.contains("back of one-sided")).unwrap_or_else(|| panic!("{warnings:?}"));
    assert!(w.contains("\"floor\""), "{w}");
    // The floor's back receives about a sixth of the lamp's flux, the largest share.
    assert!(w.find("\"floor\"") < w.find("\"ceiling\"").or(Some(usize::MAX)), "{w}");
}

#[test]
fn a_luminaire_inside_a_box_is_reported() {
    let box_ = "[[surface]]\nname = \"crate\"\nshape = \"box\"\nmaterial = \"grey\"\nmin = [0.4, 0.4, 0.4]\nmax = [0.6, 0.6, 0.6]\n";
    let (_, s) = solved(&room(false, box_));
    let warnings = texts(&s.warnings);
    assert!(
        warnings.iter().any(|w| w.contains("luminaire \"lamp\"") && w.contains("none of its light")),
        "{warnings:?}"
    );
    assert!(s.warnings.iter().any(|w| matches!(w, Warning::LuminaireUnseen { luminaire, .. } if luminaire == "lamp")));
}

#[test]
fn probes_facing_into_a_surface_or_behind_one_are_reported() {
    let probes = "[[probe]]\nname = \"down\"\nposition = [0.5, 0, 0.5]\nnormal = [0, -1, 0]\n\
                  [[probe]]\nname = \"cellar\"\nposition = [0.5, -0.5, 0.5]\nnormal = [0, 1, 0]\n\
                  [[grid]]\nname = \"under\"\norigin = [0.1, -0.2, 0.1]\nedge_u = [0, 0, 0.8]\nedge_v = [0.8, 0, 0]\nresolution = [3, 3]\n";
    let (_, s) = solved(&room(false, probes));
    let warnings = texts(&s.warnings);
    let has = |a: &str, b: &str| warnings.iter().any(|w| w.contains(a) && w.contains(b));
    assert!(has("probe \"down\"", "points into the surface it lies on (\"floor\")"), "{warnings:?}");
    assert!(has("probe \"cellar\"", "lies behind one"), "{warnings:?}");
    assert!(has("grid \"under\"", "lies behind one"), "{warnings:?}");
}

/// A crate standing on the floor of the closed room: its bottom sends nothing, its sides
/// touch the floor, so the kernel's columns spread about 1.
const CRATE: &str = "[[surface]]\nname = \"crate\"\nshape = \"box\"\nmaterial = \"grey\"\nmin = [0.2, 0, 0.3]\n\
                     max = [0.45, 0.33, 0.6]\nrotate_y_deg = 17\n";

#[test]
fn a_negative_escaped_flux_is_explained_and_bounded_by_the_kernels_columns() {
    let (scene, mut s) = solved(&room(false, CRATE));
    s.energy.escaped = -6.8385;
    let w = texts(&physics_warnings(&scene, &s.model, &s.x, &s.energy));
    let w = w.iter().find(|w| w.contains("negative")).unwrap_or_else(|| panic!("{w:?}"));
    assert!(w.contains("-6.8385 lm") && w.contains("discretization error") && w.contains("0.684 %"), "{w}");
    // The columns' range and their deviation from 1 weighted by the solved flux, computed
    // here from the balance's own identity: escaped = Σ Φ (1 − s) (the lamp's light all lands).
    let (areas, k) = (s.model.mesh.patches.iter().map(|p| p.exposed).collect::<Vec<_>>(), s.model.kernel.cells());
    let shares = sent_shares(&s.model.kernel, &areas, &s.model.mirrors);
    let cells = s.model.kernel.directions.cells();
    let flux = |c: usize| areas[c / k] * cells[c % k].projected * s.x[c];
    let either: f64 = (0..shares.len()).map(|c| flux(c) * (shares[c] - 1.0).abs()).sum();
    let high = (0..shares.len()).filter(|&c| flux(c) > 0.0).map(|c| shares[c]).fold(0.0, f64::max);
    assert!(high > 1.0 && either > 0.0, "{high} {either}");
    assert!(w.contains(&format!("and {high:.5} where a closed scene has 1")), "{w}");
    assert!(w.contains(&format!("deviation either way {either:.4} lm")) && w.contains("largest part"), "{w}");
}

#[test]
fn the_escaped_flux_is_the_outgoing_flux_weighted_by_the_columns_shortfall() {
    // escaped = Σ_(j,m) A_j μ_m x_jm (1 − s_jm) + the luminaires' light landing nowhere:
    // the energy balance and the kernel's columns computed apart, on a room where the
    // columns are not all 1 (the crate) and on one with an opening (no north wall), the
    // latter with both kernels.
    let open =
        room(false, "").replace("[[surface]]\nname = \"north\"", "[[surface]]\nname = \"north\"\ntwo_sided = false");
    let open = open.replace(
        "origin = [0, 0, 1]\nedge_u = [0, 1, 0]\nedge_v = [1, 0, 0]",
        "origin = [0, 0, 1]\nedge_u = [0, 0.5, 0]\nedge_v = [1, 0, 0]",
    );
    // The hierarchy's columns come from its links run backwards (`Gᵀ`, no expansion).
    let hierarchical = open.replace(
        "patch_size = 0.25\nkernel = \"uniform\"\n",
        "patch_size = 0.125\nkernel = \"hierarchical\"\nroot_size = 0.5\n",
    );
    assert!(hierarchical.contains("hierarchical"));
    for text in [room(false, CRATE), open, hierarchical] {
        let (_, s) = solved(&text);
        let (m, e) = (&s.model, &s.energy);
        let areas: Vec<f64> = m.mesh.patches.iter().map(|p| p.exposed).collect();
        let (shares, k, cells) =
            (sent_shares(&m.kernel, &areas, &m.mirrors), m.kernel.cells(), m.kernel.directions.cells());
        let from_surfaces: f64 =
            (0..shares.len()).map(|c| areas[c / k] * cells[c % k].projected * s.x[c] * (1.0 - shares[c])).sum();
        let from_luminaires: f64 = e.luminaire_emitted.iter().zip(&m.direct.intercepted).map(|(a, b)| a - b).sum();
        let identity = from_surfaces + from_luminaires;
        assert!((identity - e.escaped).abs() < 1e-9 * e.emitted, "{identity} against {}", e.escaped);
        assert!(e.escaped.abs() > 1e-3 * e.emitted, "a case whose columns are not all 1: {}", e.escaped);
    }
}

/// The room with its north wall `height` high instead of 1 (a gap above it), or without it.
fn gapped(height: Option<f64>) -> String {
    let north = "[[surface]]\nname = \"north\"\nshape = \"rectangle\"\nmaterial = \"grey\"\norigin = [0, 0, 1]\nedge_u = [0, 1, 0]\nedge_v = [1, 0, 0]\n";
    let text = room(false, "");
    assert!(text.contains(north));
    let wall = height.map_or(String::new(), |h| north.replace("edge_u = [0, 1, 0]", &format!("edge_u = [0, {h}, 0]")));
    text.replace(north, &wall)
}

#[test]
fn light_escaping_through_a_small_gap_is_reported_and_an_open_side_is_not() {
    let (_, s) = solved(&gapped(Some(0.85)));
    let warnings = texts(&s.warnings);
    let w = warnings.iter().find(|w| w.contains("opening")).unwrap_or_else(|| panic!("{warnings:?}"));
    // The gap is 0.15 m² of the 5.85 m² of surfaces.
    let area: f64 = w.split("an opening of about ").nth(1).and_then(|r| r.split(' ').next()).unwrap().parse().unwrap();
    assert!((area / 0.15 - 1.0).abs() < 0.1, "{w}");
    assert!(w.contains("missing wall") && w.contains("\"ceiling\""), "{w}");
    let (_, s) = solved(&gapped(None));
    assert!(s.energy.escaped > 0.1 * s.energy.emitted, "{:?}", s.energy);
    assert!(!s.warnings.iter().any(|w| matches!(w, Warning::SmallOpening { .. })), "{:?}", s.warnings);
}

/// The luminaires' direct light landing on the patches beyond their flux (its integration
/// error) is a part of a negative escaped flux that the kernel's columns do not bound: it
/// is stated apart.
#[test]
fn a_negative_escape_names_the_luminaires_part_apart_from_the_kernels() {
    let (scene, mut s) = solved(&room(false, CRATE));
    s.model.direct.intercepted[0] += 3.0;
    s.energy.escaped = -5.0;
    let w = texts(&physics_warnings(&scene, &s.model, &s.x, &s.energy));
    let w = w.iter().find(|w| w.contains("negative")).unwrap_or_else(|| panic!("{w:?}"));
    let landed: f64 = s.model.direct.intercepted.iter().sum();
    let beyond = landed - s.energy.luminaire_emitted.iter().sum::<f64>();
    assert!((beyond - 3.0).abs() < 0.1, "the lamp's own integration error is small: {beyond}");
    let (lamps, kernel) =
        (format!("Of it, {:.4} lm is the luminaires'", -beyond), format!("the rest, {:.4} lm", beyond - 5.0));
    assert!(w.contains(&lamps) && w.contains(&kernel), "{w}");
}

#[test]
fn a_probe_in_the_near_field_of_a_patch_is_reported_with_the_patch() {
    // The west wall's patches are 25 cm squares (35 cm across): 2 cm is within 0.4 of that,
    // 20 cm is not.
    let probes = "[[probe]]\nname = \"by the wall\"\nposition = [0.02, 0, 0.5]\nnormal = [0, 1, 0]\n\
                  [[probe]]\nname = \"a little off\"\nposition = [0.2, 0, 0.5]\nnormal = [0, 1, 0]\n";
    let (_, s) = solved(&room(false, probes));
    let warnings = texts(&s.warnings);
    let near: Vec<&String> = warnings.iter().filter(|w| w.contains("closer than")).collect();
    assert_eq!(near.len(), 1, "{warnings:?}");
    assert!(
        near[0].contains("probe \"by the wall\" lies 2.00 cm from a patch of \"west\" 35.4 cm across"),
        "{}",
        near[0]
    );
}

/// A warning's one-line form is its first sentence, at most `LINE` characters; identical
/// lines are merged with their count; a small negative escaped flux is a note.
#[test]
fn warnings_are_told_in_one_line_merged_and_a_small_negative_escape_is_a_note() {
    use ugo::io::{LINE, NOTE_SHARE, NegativeEscape, merged, one_line, told};
    assert_eq!(one_line("first part; second. third"), "first part");
    assert_eq!(one_line("a. b; c"), "a");
    let long = "x".repeat(3 * LINE);
    assert_eq!(one_line(&long).chars().count(), LINE);
    assert!(one_line(&long).ends_with('…'));
    let lines = ["a", "b", "a", "a"].map(String::from);
    assert_eq!(merged(lines), [("a".to_string(), 3), ("b".to_string(), 1)]);
    let escape = |escaped: f64, either: f64| {
        Warning::NegativeEscape(NegativeEscape {
            escaped,
            emitted: 1000.0,
            luminaires: None,
            low: 0.99,
            high: 1.01,
            worst: None,
            over: 0.0,
            either,
        })
    };
    // the classroom's −0.088 %: a note; 1 % of the flux emitted, either way: a warning
    assert!(escape(-0.88, 0.9).is_note());
    assert!(!escape(-NOTE_SHARE * 1000.0, 0.9).is_note() && !escape(-0.88, NOTE_SHARE * 1000.0).is_note());
    let probe =
        Warning::Probe { probe: "p".into(), fault: ugo::io::SensorFault::IntoSurface { surface: "floor".into() } };
    assert!(!probe.is_note());
    let both = [&probe, &probe];
    let lines = told(&both, false);
    assert_eq!(lines.len(), 1);
    assert!(lines[0].ends_with("(×2)") && !lines[0].contains("readings are not of the room"), "{lines:?}");
    assert!(told(&both, true)[0].contains("its readings are not of the room"));
}

/// `--strict` stops before the solve for a warning the model shows (nothing written), and
/// after it for one about the solved field, with the solution written with its warnings;
/// a warning is one line on the terminal unless `--verbose`.
#[test]
fn strict_fails_before_the_solve_or_writes_the_solution_and_verbose_gives_the_whole_text() {
    use crate::support::{scratch, ugo};
    let dir = scratch("strict-warnings");
    let run = |name: &str, text: &str, flags: &[&str]| {
        let case = dir.write(&format!("{name}.toml"), text);
        let out = dir.join(format!("{name}.h5"));
        let args = [&["solve", case.to_str().unwrap(), "-o", out.to_str().unwrap()], flags].concat();
        let o = ugo(&args);
        (o.status.success(), String::from_utf8_lossy(&o.stderr).into_owned(), out)
    };
    // a probe facing into the floor: found before the solve
    let probe = "[[probe]]\nname = \"down\"\nposition = [0.5, 0, 0.5]\nnormal = [0, -1, 0]\n";
    let (ok, err, out) = run("before", &room(false, probe), &["--strict"]);
    assert!(!ok && err.contains("before the solve") && err.contains("\"down\""), "{err}");
    assert!(!out.exists(), "nothing written");
    // the floor facing the wrong way: light lost on its back, found in the solved field
    let (ok, err, out) = run("after", &room(true, ""), &["--strict"]);
    assert!(!ok && err.contains("the solution is written with them"), "{err}");
    let file = hdf5::File::open(&out).unwrap();
    let stored: Vec<hdf5::types::VarLenUnicode> = file.dataset("warnings").unwrap().read_raw().unwrap();
    let whole = stored.iter().find(|w| w.as_str().contains("back of one-sided")).unwrap().to_string();
    assert!(whole.contains("two_sided"), "the whole text in /warnings: {whole}");
    let warning_lines: Vec<&str> = err.lines().filter(|l| l.contains("back of one-sided")).collect();
    assert!(warning_lines.iter().all(|l| !l.contains("two_sided")), "one line: {err}");
    let (ok, err, _) = run("verbose", &room(true, ""), &["--verbose"]);
    assert!(ok && err.contains("two_sided"), "--verbose gives the whole text: {err}");
}

/// The closed lecture hall at three times its case's link tolerance (9e-2): of its escaped flux,
/// the leaves' closures account for a small part (its real gaps), and the rest is the
/// hierarchy's links' own loss, told as such when beyond 1 % of the emitted flux, and never
/// as an opening (which the columns alone would have blamed). The loss was 1.04 % at 9e-2
/// while a cluster sent the mean of all its faces; since clusters send by facing
/// (`docs/hierarchy.md`, "Clusters send by facing") 604.7 lm of 192,001.7 (0.31 %); since
/// a cluster's faces count by their openness ("A cluster's faces by their openness") the
/// links gain 244.2 lm (−0.13 %), the gaps lose 6.2 lm, and no warning: the links' balance
/// is held within 0.5 % either way. Since its slots and concave edges are graded the solve
/// takes four to five minutes: `make test-long` runs it, `make test` does not.
#[test]
#[ignore = "four minutes: make test-long"]
fn the_hierarchys_own_loss_of_light_is_told_apart_from_an_opening() {
    let path = Path::new("cases/lecture-hall.toml");
    let text = std::fs::read_to_string(path).unwrap();
    assert!(text.contains("link_tolerance = 0.03"), "the hall's case changed");
    let text = text.replace("link_tolerance = 0.03", "link_tolerance = 0.09");
    let scene = Scene::parse(path, text).unwrap_or_else(|e| panic!("{e}"));
    let s = solve_case(&scene, &Job::default(), &ugo::progress::Silent).unwrap();
    let (m, e) = (&s.model, &s.energy);
    let areas: Vec<f64> = m.mesh.patches.iter().map(|p| p.exposed).collect();
    let sent = sent_shares(&m.kernel, &areas, &m.mirrors);
    let closures = closure_shares(&m.kernel, &sent, false);
    let (k, cells) = (m.kernel.cells(), m.kernel.directions.cells());
    let flux = |c: usize| areas[c / k] * cells[c % k].projected * s.x[c].max(0.0);
    let geometry: f64 = (0..sent.len()).map(|c| flux(c) * (1.0 - closures[c])).sum();
    let links: f64 = (0..sent.len()).map(|c| flux(c) * (closures[c] - sent[c])).sum();
    assert!(geometry.abs() < 2e-3 * e.emitted, "a closed hall's gaps: {geometry} of {}", e.emitted);
    eprintln!(
        "the lecture hall at 9e-2: the links' loss {links:.1} lm, the gaps' {geometry:.1} lm, of {:.1} lm",
        e.emitted
    );
    assert!(links.abs() < 5e-3 * e.emitted, "the links' loss {links}, the gaps' {geometry}");
    let told = texts(&s.warnings);
    let warned = told.iter().find(|w| w.contains("lost by the hierarchy's links"));
    match links > 1e-2 * e.emitted {
        true => assert!(warned.is_some_and(|w| w.starts_with(&format!("{links:.4} lm"))), "{told:?}"),
        false => assert!(warned.is_none(), "{told:?}"),
    }
    assert!(!s.warnings.iter().any(|w| matches!(w, Warning::SmallOpening { .. })), "{told:?}");
}

/// The links' own loss is told with its figure, its share of the emitted flux and what to
/// do about it.
#[test]
fn the_links_own_loss_is_told_with_its_share_and_the_way_out() {
    let told = Warning::KernelLoss { lost: 2074.3277, emitted: 192_001.7 }.to_string();
    assert!(told.starts_with("2074.3277 lm (1.1 % of the flux emitted) is lost by the hierarchy's links"), "{told}");
    assert!(told.contains("a smaller link_tolerance loses less"), "{told}");
}

/// The unit room with 16 direction cells, its walls named in `mirrors` of a 90 % mirror,
/// `kernel` the `[discretization]`'s kernel.
fn mirrored(mirrors: &[&str], kernel: &str) -> String {
    let mut text = room(false, "[[material]]\nname = \"mirror\"\ntype = \"mirror\"\nreflectance = 0.9\n")
        .replace("kernel = \"uniform\"\n", &format!("directions = 16\nkernel = \"{kernel}\"\n"));
    for wall in mirrors {
        let at = text.find(&format!("name = \"{wall}\"\nshape = \"rectangle\"\nmaterial = \"grey\"")).unwrap();
        let grey = at + text[at..].find("\"grey\"").unwrap();
        text.replace_range(grey..grey + 6, "\"mirror\"");
    }
    text
}

#[test]
fn a_mirror_reflected_cell_to_cell_is_told_with_its_cause_and_one_carried_by_images_is_not() {
    let told = |mirrors: &[&str], kernel: &str| {
        let (scene, s) = solved(&mirrored(mirrors, kernel));
        let w: Vec<&Warning> = s.warnings.iter().filter(|w| matches!(w, Warning::MirrorsByCells { .. })).collect();
        assert!(scene.materials.iter().any(|m| m.name == "mirror"));
        w.iter().map(ToString::to_string).collect::<Vec<String>>()
    };
    // A plane mirror lit by a point lamp: the uniform kernel carries it by images.
    assert!(told(&["north"], "uniform").is_empty());
    let w = told(&["north"], "hierarchical");
    assert!(
        w.len() == 1
            && w[0].contains("mirror \"north\" reflects cell to cell")
            && w[0].contains("hierarchical kernel carries no images")
            && w[0].contains("about 36°")
            && w[0].contains("--kernel uniform"),
        "{w:?}"
    );
    // Two mirrors facing each other would need images of images.
    let w = told(&["north", "south"], "uniform");
    assert!(w.len() == 1 && w[0].contains("\"north\"") && w[0].contains("\"south\""), "{w:?}");
    assert!(w[0].contains("facing another mirror"), "{w:?}");
}
