//! The UGR of CIE 117 at an `[[observer]]` (`ugo::readout::ugr`, `docs/photometry.md` "UGR")
//! against a calculation by hand from first principles: a 0.6 × 0.6 m panel in a black
//! 4 m box whose walls shine at `L_e`, so that the background luminance is exactly `L_e`
//! (a closed enclosure of uniform luminance gives `E = π L_e` on any plane inside).

use super::{room, solved};
use crate::support::scratch;
use glam::DVec3;
use ugo::readout::ugr::{UgrReading, read_observers};
use ugo::scene::Scene;

/// A 0.6 × 0.6 m panel (metres, units type 2), axially symmetric: 1000 cd at the nadir,
/// 600 cd at 45°, none at 90°.
pub(super) const PANEL: &str = "IESNA:LM-63-2002\n[TEST] panel\nTILT=NONE\n1 -1 1 3 1 1 2 0.6 0.6 0\n1 1 0\n\
                     0 45 90\n0\n1000 600 0\n";

/// The walls' luminance, cd/m².
pub(super) const WALLS: f64 = 10.0;
pub(super) const EYE: [f64; 3] = [0.8, 1.2, 2.0];
const AHEAD: [f64; 3] = [3.0, 3.0, 2.5];

/// The observer's reading in the black box of walls at `walls` cd/m² with panels at
/// `panels` (each dimmed by `multiplier`) and the tables `more`, the eye at [`EYE`]
/// looking along `+x`.
fn reading(walls: f64, panels: &[[f64; 3]], multiplier: f64, more: &str) -> UgrReading {
    let dir = scratch("ugr");
    std::fs::write(dir.as_ref().join("panel.ies"), PANEL).expect("writable");
    let mut text = room(4.0, 0.0, walls) + more;
    for (i, [x, y, z]) in panels.iter().enumerate() {
        text += &format!(
            "[[luminaire]]\nname = \"panel {i}\"\ntype = \"ies\"\nfile = \"panel.ies\"\nposition = [{x}, {y}, {z}]\n\
             multiplier = {multiplier}\n"
        );
    }
    text += &format!("[[observer]]\nname = \"desk\"\nposition = {EYE:?}\nlook = [1, 0, 0]\nugr_limit = 19\n");
    let path = dir.as_ref().join("case.toml");
    std::fs::write(&path, text).expect("writable");
    let scene = Scene::load(&path).unwrap_or_else(|e| panic!("{e}"));
    let (model, field) = solved(&scene);
    read_observers(&scene.observers, &model, &field).remove(0)
}

/// UGR by hand for the panel at `at` seen from [`EYE`] looking along `+x`.
pub(super) fn by_hand(at: [f64; 3], background: f64) -> f64 {
    let [dx, dy, dz] = [at[0] - EYE[0], at[1] - EYE[1], at[2] - EYE[2]];
    let r2 = dx * dx + dy * dy + dz * dz;
    let r = r2.sqrt();
    // The panel faces down: seen at γ from its nadir, its projected area is 0.36 cos γ.
    let cos_gamma = dy / r;
    let gamma = cos_gamma.acos().to_degrees();
    let intensity = if gamma <= 45.0 { 1000.0 - 400.0 * gamma / 45.0 } else { 600.0 * (90.0 - gamma) / 45.0 };
    let area = 0.36 * cos_gamma;
    let luminance = intensity / area;
    let omega = area / r2;
    // Guth: σ from the line of sight (+x), τ from the vertical about it.
    let sigma = (dx / r).acos().to_degrees();
    let tau = dz.abs().atan2(dy).to_degrees();
    let ln_p = (35.2 - 0.31889 * tau - 1.22 * (-2.0 * tau / 9.0).exp()) / 1000.0 * sigma
        + (21.0 + 0.26667 * tau - 0.002963 * tau.powi(2)) / 100000.0 * sigma.powi(2);
    let p = ln_p.exp();
    8.0 * (0.25 / background * luminance.powi(2) * omega / (p * p)).log10()
}

#[test]
fn one_panel_ahead_matches_the_hand_calculation() {
    let r = reading(WALLS, &[AHEAD], 1.0, "");
    assert!((r.background - WALLS).abs() < 1e-9 * WALLS, "L_b {} against {WALLS}", r.background);
    assert_eq!(r.sources.len(), 1);
    let (ugr, expected) = (r.ugr(), by_hand(AHEAD, WALLS));
    assert!((ugr - expected).abs() < 1e-6, "UGR {ugr} against {expected} by hand");
    assert!(r.sources[0].valid(), "ω = {} sr", r.sources[0].solid_angle);
}

#[test]
fn a_panel_behind_the_eye_or_below_its_line_of_sight_adds_nothing() {
    let alone = reading(WALLS, &[AHEAD], 1.0, "");
    let behind = reading(WALLS, &[AHEAD, [0.3, 3.0, 2.0]], 1.0, "");
    let below = reading(WALLS, &[AHEAD, [3.0, 0.5, 2.0]], 1.0, "");
    for r in [&behind, &below] {
        assert_eq!(r.sources.len(), 1);
        assert!((r.ugr() - alone.ugr()).abs() < 1e-12, "{} against {}", r.ugr(), alone.ugr());
    }
}

#[test]
fn a_panel_hidden_behind_a_plate_adds_nothing() {
    // A plate between the eye and a second panel, shining like the walls on both sides.
    let plate = format!(
        "[[surface]]\nname = \"plate\"\nshape = \"rectangle\"\nmaterial = \"grey\"\norigin = [2, 2.5, 0.3]\n\
         edge_u = [1.5, 0, 0]\nedge_v = [0, 0, 1]\ntwo_sided = true\nemission = {{ luminance = {WALLS} }}\n"
    );
    let r = reading(WALLS, &[AHEAD, [3.0, 3.0, 0.8]], 1.0, &plate);
    assert_eq!(r.sources.len(), 1);
    let (ugr, expected) = (r.ugr(), by_hand(AHEAD, r.background));
    assert!((ugr - expected).abs() < 1e-6, "UGR {ugr} against {expected} by hand");
}

#[test]
fn halving_every_light_lowers_the_ugr_by_8_log10_2() {
    // ω and p stay; L² falls by 4 and L_b by 2.
    let full = reading(WALLS, &[AHEAD], 1.0, "");
    let half = reading(WALLS / 2.0, &[AHEAD], 0.5, "");
    let drop = full.ugr() - half.ugr();
    assert!((drop - 8.0 * 2f64.log10()).abs() < 1e-9, "dropped by {drop}");
}

#[test]
fn no_panel_in_view_has_no_glare() {
    let r = reading(WALLS, &[[0.3, 3.0, 2.0]], 1.0, "");
    assert!(r.sources.is_empty() && r.ugr() == f64::NEG_INFINITY);
}

#[test]
fn an_observer_is_validated_key_by_key() {
    let base = room(4.0, 0.5, 10.0);
    let rejected = |observer: &str, key: &str, words: &str| {
        let text = format!("{base}[[observer]]\nname = \"eye\"\nposition = [1, 1.2, 1]\n{observer}");
        let error = Scene::parse(std::path::Path::new("cases/test.toml"), text).expect_err("rejected");
        let shown = error.to_string();
        assert!(shown.contains("[[observer]] \"eye\" (#1)") && shown.contains(key) && shown.contains(words), "{shown}");
    };
    rejected("look = [0, -1, 0]\n", "look", "from the vertical");
    rejected("look = [0, 0, 0]\n", "look", "non-zero");
    rejected("look = [1, 0, 0]\nugr_limit = 50\n", "ugr_limit", "within 0 and 40");
    let misspelled =
        format!("{base}[[observer]]\nname = \"eye\"\nposition = [1, 1.2, 1]\nlook = [1, 0, 0]\nugr_lim = 19\n");
    assert!(Scene::parse(std::path::Path::new("cases/test.toml"), misspelled).is_err());
    let eye = DVec3::new(1.0, 1.2, 1.0);
    let text = format!("{base}[[observer]]\nname = \"eye\"\nposition = [1, 1.2, 1]\nlook = [2, 0, 0]\n");
    let scene = Scene::parse(std::path::Path::new("cases/test.toml"), text).expect("valid");
    assert_eq!((scene.observers[0].position, scene.observers[0].look), (eye, DVec3::X));
}

#[test]
fn a_panel_close_to_the_eye_is_outside_the_formulas_solid_angles() {
    // 0.36 cos γ / r² = 0.28 sr at 0.92 m.
    let r = reading(WALLS, &[AHEAD, [1.5, 1.8, 2.0]], 1.0, "");
    assert_eq!((r.sources.len(), r.outside_validity()), (2, 1));
    assert!(r.sources[1].solid_angle > 0.1, "ω = {} sr", r.sources[1].solid_angle);
}

/// `ugo solve` of the case `text` in `dir` (`case.toml` → `res.h5`): the file and the summary.
pub(super) fn solved_file(dir: &std::path::Path, text: &str) -> (hdf5::File, String) {
    let case = dir.join("case.toml");
    std::fs::write(&case, text).expect("writable");
    let out = dir.join("res.h5");
    let o = crate::support::ugo(&["solve", case.to_str().unwrap(), "-o", out.to_str().unwrap()]);
    let stdout = String::from_utf8_lossy(&o.stdout).into_owned();
    assert!(o.status.success(), "{stdout}{}", String::from_utf8_lossy(&o.stderr));
    (hdf5::File::open(&out).unwrap(), stdout)
}

/// Every light scene reads its observers under its dimmed luminaires and its own field
/// (issue 38, point 1): all at half gives `UGR − 8 log10 2` exactly, the panel off no
/// source, in the summary and in `/light_scenes/NAME/observers`.
#[test]
fn each_light_scene_reads_its_own_ugr() {
    let dir = scratch("ugr-scenes");
    std::fs::write(dir.as_ref().join("panel.ies"), PANEL).expect("writable");
    let mut text = room(4.0, 0.0, WALLS) + "group = \"walls\"\n";
    let [x, y, z] = AHEAD;
    text += &format!(
        "[[luminaire]]\nname = \"panel\"\ntype = \"ies\"\nfile = \"panel.ies\"\nposition = [{x}, {y}, {z}]\ngroup = \"panel\"\n\
         [[observer]]\nname = \"desk\"\nposition = {EYE:?}\nlook = [1, 0, 0]\nugr_limit = 19\n\
         [[light_scene]]\nname = \"full\"\ngroups = {{ walls = 1, panel = 1 }}\n\
         [[light_scene]]\nname = \"half\"\ngroups = {{ walls = 0.5, panel = 0.5 }}\n\
         [[light_scene]]\nname = \"dark\"\ngroups = {{ walls = 1, panel = false }}\n"
    );
    let (file, stdout) = solved_file(dir.as_ref(), &text);
    let ugr = |scene: &str| {
        file.dataset(&format!("light_scenes/{scene}/observers/ugr")).unwrap().read_raw::<f64>().unwrap()[0]
    };
    let own = file.dataset("observers/ugr").unwrap().read_raw::<f64>().unwrap()[0];
    assert!((ugr("full") - own).abs() < 1e-9, "full {} against the case's {own}", ugr("full"));
    let drop = ugr("full") - ugr("half");
    assert!((drop - 8.0 * 2f64.log10()).abs() < 1e-9, "dropped by {drop}");
    assert_eq!(ugr("dark"), f64::NEG_INFINITY);
    let dark = stdout.split("light scene \"dark\"").nth(1).expect("the dark scene is reported");
    let line = dark.lines().find(|l| l.trim_start().starts_with("desk")).expect("its observer line");
    assert!(line.contains("no source") && line.contains("met"), "{line}");
}

/// A `[[grid]]`'s UGR is the largest of the observers that name it, checked against its
/// `target`'s `ugr` (`UGR_L`) in the summary, the HDF5 file and the report (issue 38, point 1).
#[test]
fn a_grids_ugr_is_the_largest_of_its_observers() {
    let dir = scratch("ugr-grid");
    std::fs::write(dir.as_ref().join("panel.ies"), PANEL).expect("writable");
    let [x, y, z] = AHEAD;
    let text = room(4.0, 0.0, WALLS)
        + &format!(
            "[[luminaire]]\nname = \"panel\"\ntype = \"ies\"\nfile = \"panel.ies\"\nposition = [{x}, {y}, {z}]\n\
             [[grid]]\nname = \"desk\"\norigin = [0.5, 0.8, 0.5]\nedge_u = [3, 0, 0]\nedge_v = [0, 0, 3]\n\
             resolution = [3, 3]\nnormal = [0, 1, 0]\ntarget = {{ ugr = 16 }}\n\
             [[observer]]\nname = \"near\"\nposition = {EYE:?}\nlook = [1, 0, 0]\ngrid = \"desk\"\n\
             [[observer]]\nname = \"far\"\nposition = [0.8, 1.2, 0.6]\nlook = [1, 0, 0]\ngrid = \"desk\"\n\
             [[observer]]\nname = \"elsewhere\"\nposition = [0.8, 1.8, 2.5]\nlook = [1, 0, 0]\n"
        );
    let (file, stdout) = solved_file(dir.as_ref(), &text);
    let observers = file.dataset("observers/ugr").unwrap().read_raw::<f64>().unwrap();
    let grid = file.group("grids/desk").unwrap();
    let attr = |name: &str| grid.attr(name).unwrap().read_scalar::<f64>().unwrap();
    assert_eq!(attr("UGR"), observers[0].max(observers[1]), "observers {observers:?}");
    assert!(observers[2] > attr("UGR"), "the one naming no grid does not count: {observers:?}");
    assert_eq!(attr("UGR_target"), 16.0);
    let line = stdout.lines().find(|l| l.trim_start().starts_with("desk") && l.contains("16")).expect("its line");
    let verdict = if attr("UGR") <= 16.0 { "met" } else { "NOT MET" };
    assert!(line.contains(&format!("{:.2}", attr("UGR"))) && line.contains(verdict), "{line}");
    let (out, page) = (dir.as_ref().join("res.h5"), dir.as_ref().join("res.html"));
    let o = crate::support::ugo(&["report", out.to_str().unwrap(), "-o", page.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let html = std::fs::read_to_string(&page).unwrap();
    assert!(
        html.contains("<th>UGR_L</th>") && html.contains(&format!("<td>{:.1}</td>", attr("UGR"))),
        "the grid table"
    );
}

#[test]
fn a_grids_ugr_limit_and_an_observers_grid_are_validated_naming_the_line() {
    let base = room(4.0, 0.5, 10.0)
        + "[[grid]]\nname = \"desk\"\norigin = [0.5, 0.8, 0.5]\nedge_u = [3, 0, 0]\nedge_v = [0, 0, 3]\n\
           resolution = [3, 3]\n";
    let rejected = |more: &str, table: &str, key: &str, words: &str| {
        let error =
            Scene::parse(std::path::Path::new("cases/test.toml"), format!("{base}{more}")).expect_err("rejected");
        let shown = error.to_string();
        let line = shown.contains("line ");
        assert!(shown.contains("cases/test.toml") && shown.contains(table) && shown.contains(key), "{shown}");
        assert!(shown.contains(words) && line, "{shown}");
    };
    let eye = "[[observer]]\nname = \"eye\"\nposition = [1, 1.2, 1]\nlook = [1, 0, 0]\n";
    rejected("target = { ugr = 19 }\n", "[[grid]] \"desk\" (#1)", "target", "needs an [[observer]]");
    rejected("target = { ugr = 19 }\n", "[[grid]] \"desk\" (#1)", "target", "grid = \"desk\"");
    rejected("target = { ugr = 50 }\n", "[[grid]] \"desk\" (#1)", "target", "within 0 and 40");
    rejected(&format!("{eye}grid = \"bench\"\n"), "[[observer]] \"eye\" (#1)", "grid", "names no [[grid]]");
    let fine = format!("{base}target = {{ ugr = 19 }}\n{eye}grid = \"desk\"\n");
    let scene = Scene::parse(std::path::Path::new("cases/test.toml"), fine).expect("valid");
    assert_eq!((scene.grids[0].target.ugr, scene.observers[0].grid.as_deref()), (Some(19.0), Some("desk")));
}
