//! The UGR on a `[[glare_grid]]` (`ugo::readout::glare_grid`, `docs/photometry.md` "UGR on a
//! grid of observers"): a one-position grid against the calculation by hand of `ugr.rs`,
//! every position and view against an `[[observer]]` written there by hand, positions
//! mirrored about the room's plane of symmetry against each other, the table's validation,
//! and `ugo solve`'s summary, CSV and `/glare_grids`.

use super::ugr::{EYE, PANEL, WALLS, by_hand, solved_file};
use super::{room, solved};
use crate::support::scratch;
use std::path::Path;
use ugo::readout::glare_grid::{GlareGridReading, read_glare_grids};
use ugo::readout::ugr::read_observers;
use ugo::scene::Scene;

/// `[[luminaire]]` tables of the test panel at `at`.
fn panels(at: &[[f64; 3]]) -> String {
    let one = |(i, [x, y, z]): (usize, &[f64; 3])| {
        format!(
            "[[luminaire]]\nname = \"panel {i}\"\ntype = \"ies\"\nfile = \"panel.ies\"\nposition = [{x}, {y}, {z}]\n"
        )
    };
    at.iter().enumerate().map(one).collect()
}

/// The scene of `text` (beside the panel's file) and its glare grids read on its solved field.
fn read(text: &str) -> (Scene, Vec<GlareGridReading>) {
    let dir = scratch("glare-grid");
    std::fs::write(dir.as_ref().join("panel.ies"), PANEL).expect("writable");
    let path = dir.as_ref().join("case.toml");
    std::fs::write(&path, text).expect("writable");
    let scene = Scene::load(&path).unwrap_or_else(|e| panic!("{e}"));
    let (model, field) = solved(&scene);
    let observers = read_observers(&scene.observers, &model, &field);
    let mut grids = read_glare_grids(&scene.glare_grids, &model, &field);
    grids.push(GlareGridReading { grid: grids[0].grid.clone(), readings: observers });
    (scene, grids)
}

#[test]
fn a_one_position_grid_matches_the_hand_calculation() {
    let ahead = [3.0, 3.0, 2.5];
    let [x, y, z] = EYE;
    let text = room(4.0, 0.0, WALLS)
        + &panels(&[ahead])
        + &format!(
            "[[glare_grid]]\nname = \"desk\"\norigin = [{}, {y}, {}]\nedge_u = [0.4, 0, 0]\nedge_v = [0, 0, 0.4]\n\
             resolution = [1, 1]\nlook = [1, 0, 0]\n",
            x - 0.2,
            z - 0.2
        );
    let (_, grids) = read(&text);
    let (ugr, expected) = (grids[0].ugr(0, 0), by_hand(ahead, WALLS));
    assert!((ugr - expected).abs() < 1e-6, "UGR {ugr} against {expected} by hand");
}

/// A 3 × 2 grid at 1.2 m looking four ways, in a grey room lit by three panels.
const GRID: &str = "[[glare_grid]]\nname = \"desks\"\norigin = [0.5, 1.2, 0.5]\nedge_u = [3, 0, 0]\n\
                    edge_v = [0, 0, 3]\nresolution = [3, 2]\nlook = [1, 0, 0]\nview_step_deg = 90\nugr_limit = 19\n";

#[test]
fn every_position_and_view_is_an_observer_written_there_by_hand() {
    let mut text = room(4.0, 0.5, 0.0) + &panels(&[[2.0, 3.5, 1.0], [3.0, 3.5, 3.0], [1.0, 3.5, 2.5]]) + GRID;
    for (v, u, k) in (0..2).flat_map(|v| (0..3).flat_map(move |u| (0..4).map(move |k| (v, u, k)))) {
        let (x, z) = (0.5 + 3.0 * (u as f64 + 0.5) / 3.0, 0.5 + 3.0 * (v as f64 + 0.5) / 2.0);
        let turn = (90.0 * k as f64).to_radians();
        text += &format!(
            "[[observer]]\nname = \"{u},{v},{k}\"\nposition = [{x}, 1.2, {z}]\nlook = [{}, 0, {}]\n",
            turn.cos(),
            -turn.sin()
        );
    }
    let (scene, grids) = read(&text);
    let (grid, by_hand) = (&grids[0], &grids[1]);
    assert_eq!((grid.readings.len(), scene.glare_grids[0].views.len()), (24, 4));
    for (k, (a, b)) in grid.readings.iter().zip(&by_hand.readings).enumerate() {
        assert!(
            a.ugr() == b.ugr() || (a.ugr() - b.ugr()).abs() < 1e-9,
            "#{k}: {} against {} ({})",
            a.ugr(),
            b.ugr(),
            b.observer.name
        );
        assert!((a.background - b.background).abs() < 1e-9 * b.background, "#{k}");
    }
    let largest = grid.largest();
    let every = by_hand.readings.iter().map(|r| r.ugr()).fold(f64::NEG_INFINITY, f64::max);
    assert!(largest.ugr.is_finite() && (largest.ugr - every).abs() < 1e-9, "{largest:?} against {every}");
    assert_eq!(grid.ugr(largest.position, largest.view), largest.ugr);
    assert_eq!(grid.per_position().iter().copied().fold(f64::NEG_INFINITY, f64::max), largest.ugr);
    assert_eq!(grid.met(), Some(largest.ugr <= 19.0));
}

#[test]
fn positions_mirrored_about_the_rooms_plane_of_symmetry_read_alike() {
    // Symmetric about z = 2: a position (u, v) mirrors to (u, 1 − v), a turn θ to −θ; no
    // panel lies level with a position across the line of sight (σ = 90°, on the edge of view).
    let text = room(4.0, 0.5, 0.0)
        + &panels(&[[2.5, 3.5, 1.0], [2.5, 3.5, 3.0], [3.5, 3.5, 2.0]])
        + "[[glare_grid]]\nname = \"desks\"\norigin = [0.5, 1.2, 0.5]\nedge_u = [2, 0, 0]\nedge_v = [0, 0, 3]\n\
           resolution = [2, 2]\nlook = [1, 0, 0]\nview_step_deg = 90\n";
    let (_, grids) = read(&text);
    let g = &grids[0];
    let mut largest_difference = 0.0f64;
    for (u, v, j) in (0..2).flat_map(|u| (0..2).flat_map(move |v| (0..4).map(move |j| (u, v, j)))) {
        let (a, b) = (g.ugr(u + 2 * v, j), g.ugr(u + 2 * (1 - v), (4 - j) % 4));
        assert_eq!(a.is_finite(), b.is_finite(), "({u}, {v}) turn {j}");
        if a.is_finite() {
            largest_difference = largest_difference.max((a - b).abs());
        }
    }
    assert!(largest_difference < 1e-5, "mirrored positions differ by up to {largest_difference}");
    assert!(g.readings.iter().filter(|r| r.ugr().is_finite()).count() >= 8, "most views see a panel");
}

#[test]
fn a_glare_grid_is_validated_naming_table_key_and_line() {
    let base = room(4.0, 0.5, 10.0);
    let table = "[[glare_grid]]\nname = \"desks\"\norigin = [0.5, 1.2, 0.5]\nedge_u = [3, 0, 0]\nedge_v = [0, 0, 3]\n";
    let rejected = |more: &str, key: &str, words: &str| {
        let text = format!("{base}{table}{more}");
        let error = Scene::parse(Path::new("cases/test.toml"), text).expect_err("rejected");
        let shown = error.to_string();
        assert!(shown.contains("cases/test.toml") && shown.contains("glare_grid"), "{shown}");
        assert!(shown.contains(key) && shown.contains(words), "{shown}");
    };
    rejected("resolution = [3, 2]\nlook = [1, 0, 0]\nview_step_deg = 7\n", "view_step_deg", "line 23: must divide");
    rejected("resolution = [3, 2]\nlook = [1, 0, 0]\nview_step_deg = 0\n", "view_step_deg", "must divide");
    rejected("resolution = [0, 2]\nlook = [1, 0, 0]\n", "resolution", "from 1 to 100");
    rejected("resolution = [3, 2]\nlook = [0, 1, 0]\n", "look", "from the vertical");
    rejected("resolution = [3, 2]\nlook = [1, 0, 0]\nugr_limit = 45\n", "ugr_limit", "within 0 and 40");
    rejected("resolution = [3, 2]\nlook = [1, 0, 0]\nview_step = 90\n", "view_step", "unknown field");
    rejected("look = [1, 0, 0]\n", "resolution", "missing");
    let text = format!("{base}{table}resolution = [3, 2]\nlook = [1, 0, 0]\nview_step_deg = 45\n");
    let scene = Scene::parse(Path::new("cases/test.toml"), text).expect("valid");
    let views = &scene.glare_grids[0].views;
    assert_eq!(
        views.iter().map(|v| v.turn_deg).collect::<Vec<_>>(),
        [0.0, 45.0, 90.0, 135.0, 180.0, 225.0, 270.0, 315.0]
    );
    let quarter = views[2].look;
    assert!((quarter - glam::DVec3::NEG_Z).length() < 1e-12, "90° turns +x to −z: {quarter}");
}

#[test]
fn ugo_solve_reports_writes_the_csv_and_the_hdf5_group() {
    let dir = scratch("glare-grid-solve");
    std::fs::write(dir.as_ref().join("panel.ies"), PANEL).expect("writable");
    let text = room(4.0, 0.5, 0.0) + &panels(&[[2.0, 3.5, 1.0], [3.0, 3.5, 3.0]]) + GRID;
    let (file, stdout) = solved_file(dir.as_ref(), &text);
    let g = file.group("glare_grids/desks").unwrap();
    let ugr = g.dataset("ugr").unwrap();
    assert_eq!(ugr.shape(), [2, 3, 4]);
    let values = ugr.read_raw::<f64>().unwrap();
    let largest = g.attr("UGR_max").unwrap().read_scalar::<f64>().unwrap();
    assert_eq!(largest, values.iter().copied().fold(f64::NEG_INFINITY, f64::max));
    assert_eq!(g.attr("ugr_limit").unwrap().read_scalar::<f64>().unwrap(), 19.0);
    let line = stdout.lines().find(|l| l.trim_start().starts_with("desks")).expect("its summary line");
    let verdict = if largest <= 19.0 { "met" } else { "NOT MET" };
    assert!(line.contains(&format!("{largest:.2}")) && line.contains("3 × 2 × 4") && line.contains(verdict), "{line}");
    let csv = std::fs::read_to_string(dir.as_ref().join("res-glare-desks.csv")).expect("the CSV");
    let rows: Vec<&str> = csv.lines().filter(|l| !l.starts_with('#')).collect();
    assert_eq!(rows[0], "u,v,x,y,z,turn_deg,look_x,look_y,look_z,UGR,L_b_cd_m2,sources,outside_validity");
    assert_eq!(rows.len(), 1 + 24);
    let from_csv: Vec<f64> = rows[1..].iter().map(|r| r.split(',').nth(9).unwrap().parse().unwrap()).collect();
    for (a, b) in from_csv.iter().zip(&values) {
        assert!((a - b).abs() < 1e-5 || (a.is_infinite() && a == b), "{a} against {b}");
    }
}

/// Under light scenes every glare grid is read again with the scene's dimmed luminaires and
/// its own background (as the observers are): the scene that lights every group at 1 reads
/// what the case reads, to the solves' tolerance; one that dims a panel and turns the other
/// off reads otherwise, and has its own CSV and `/light_scenes/NAME/glare_grids`.
#[test]
fn light_scenes_read_their_own_glare_grids() {
    let dir = scratch("glare-grid-scenes");
    std::fs::write(dir.as_ref().join("panel.ies"), PANEL).expect("writable");
    let grouped = panels(&[[2.0, 3.5, 1.0], [3.0, 3.5, 3.0]])
        .replacen("position = [2, 3.5, 1]\n", "position = [2, 3.5, 1]\ngroup = \"a\"\n", 1)
        .replacen("position = [3, 3.5, 3]\n", "position = [3, 3.5, 3]\ngroup = \"b\"\n", 1);
    assert_eq!(grouped.matches("group = ").count(), 2, "{grouped}");
    let scenes = "[[light_scene]]\nname = \"all\"\ngroups = { a = 1, b = 1 }\n\
                  [[light_scene]]\nname = \"half\"\ngroups = { a = 0.5, b = false }\n";
    let text = room(4.0, 0.5, 0.0) + &grouped + GRID + scenes;
    let (file, stdout) = solved_file(dir.as_ref(), &text);
    let ugr = |path: &str| file.dataset(path).unwrap().read_raw::<f64>().unwrap();
    let (own, all, half) = (
        ugr("glare_grids/desks/ugr"),
        ugr("light_scenes/all/glare_grids/desks/ugr"),
        ugr("light_scenes/half/glare_grids/desks/ugr"),
    );
    assert_eq!((own.len(), all.len(), half.len()), (24, 24, 24));
    for (a, b) in own.iter().zip(&all) {
        assert!((a - b).abs() < 1e-6 || (a.is_infinite() && a == b), "all-on {b} against the case's {a}");
    }
    assert!(own.iter().zip(&half).any(|(a, b)| (a - b).abs() > 0.1), "the dimmed scene reads otherwise");
    let csv = std::fs::read_to_string(dir.as_ref().join("res-half-glare-desks.csv")).expect("the scene's CSV");
    assert_eq!(csv.lines().filter(|l| !l.starts_with('#')).count(), 1 + 24);
    assert_eq!(stdout.matches("glare grids ").count(), 3, "the case's block and each scene's: {stdout}");
}
