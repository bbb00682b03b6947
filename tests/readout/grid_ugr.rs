//! A `[[grid]]`'s UGR fed by `[[glare_grid]]`s (`ugo::readout::grid_ugr`, `docs/photometry.md`
//! "A grid's UGR"; issue 38): a glare grid naming a grid with a `ugr` target satisfies it
//! alone and gives the grid its largest UGR, checked against the target in the summary and
//! the HDF5 file; with an observer naming the grid too, the grid's UGR is the larger of
//! theirs; a glare grid's `grid` is validated naming file, table, key and line; each light
//! scene's grid reads that scene's glare grids; and `ugo readout` after the solve reads a
//! glare grid named after it.

use super::room;
use super::ugr::{PANEL, solved_file};
use crate::support::{scratch, ugo};
use std::path::Path;
use ugo::scene::Scene;

/// Two panels of the test panel, in groups `a` and `b`.
const PANELS: &str = "[[luminaire]]\nname = \"panel a\"\ntype = \"ies\"\nfile = \"panel.ies\"\n\
                      position = [2, 3.5, 1]\ngroup = \"a\"\n\
                      [[luminaire]]\nname = \"panel b\"\ntype = \"ies\"\nfile = \"panel.ies\"\n\
                      position = [3, 3.5, 3]\ngroup = \"b\"\n";

/// A `[[grid]]` named `name` on the floor of the 4 m room, with the `target` `ugr`.
fn grid(name: &str, ugr: f64) -> String {
    format!(
        "[[grid]]\nname = \"{name}\"\norigin = [0.5, 0.8, 0.5]\nedge_u = [3, 0, 0]\nedge_v = [0, 0, 3]\n\
         resolution = [3, 3]\nnormal = [0, 1, 0]\ntarget = {{ ugr = {ugr} }}\n"
    )
}

/// A 3 × 2 `[[glare_grid]]` at 1.2 m looking four ways, named `name`, naming the grid `grid`.
fn glare_grid(name: &str, grid: &str) -> String {
    format!(
        "[[glare_grid]]\nname = \"{name}\"\norigin = [0.5, 1.2, 0.5]\nedge_u = [3, 0, 0]\nedge_v = [0, 0, 3]\n\
         resolution = [3, 2]\nlook = [1, 0, 0]\nview_step_deg = 90\ngrid = \"{grid}\"\n"
    )
}

/// `ugo solve` of `text` in a scratch folder `name` beside the panel's file.
fn solve(name: &str, text: &str) -> (hdf5::File, String) {
    let dir = scratch(name);
    std::fs::write(dir.as_ref().join("panel.ies"), PANEL).expect("writable");
    solved_file(dir.as_ref(), text)
}

fn attr(file: &hdf5::File, group: &str, name: &str) -> f64 {
    file.group(group).unwrap().attr(name).unwrap().read_scalar::<f64>().unwrap()
}

/// The summary's line of the grid `grid` against its `UGR_L`, checked to show `ugr` and the
/// verdict of `ugr` against `limit`.
fn assert_summary_line(stdout: &str, grid: &str, ugr: f64, limit: f64) {
    let line = stdout
        .lines()
        .find(|l| l.trim_start().starts_with(grid) && l.contains(&format!("{limit}:")))
        .unwrap_or_else(|| panic!("no line for the grid {grid}: {stdout}"));
    let verdict = if ugr <= limit { ": met" } else { ": NOT MET" };
    assert!(line.contains(&format!("{ugr:.2}")) && line.contains(verdict), "{line}");
}

#[test]
fn a_glare_grid_alone_gives_its_grids_ugr_checked_against_the_target() {
    let text = room(4.0, 0.5, 0.0)
        + PANELS
        + &grid("desk", 40.0)
        + &grid("bench", 0.0)
        + &glare_grid("desks", "desk")
        + &glare_grid("seats", "bench");
    let (file, stdout) = solve("grid-ugr-alone", &text);
    for (grid, glare, limit) in [("desk", "desks", 40.0), ("bench", "seats", 0.0)] {
        let ugr = attr(&file, &format!("grids/{grid}"), "UGR");
        let largest = attr(&file, &format!("glare_grids/{glare}"), "UGR_max");
        let every = file.dataset(&format!("glare_grids/{glare}/ugr")).unwrap().read_raw::<f64>().unwrap();
        assert!(ugr.is_finite() && ugr > 0.0, "{grid}: {ugr}");
        assert!((ugr - largest).abs() < 1e-9, "{grid}: UGR {ugr} against its glare grid's largest {largest}");
        assert_eq!(largest, every.iter().copied().fold(f64::NEG_INFINITY, f64::max));
        assert_eq!(attr(&file, &format!("grids/{grid}"), "UGR_target"), limit);
        let named = file.group(&format!("glare_grids/{glare}")).unwrap().attr("grid").unwrap();
        assert_eq!(named.read_scalar::<hdf5::types::VarLenUnicode>().unwrap().as_str(), grid);
        assert_summary_line(&stdout, grid, ugr, limit);
    }
    assert!(stdout.contains("glare grid \"desks\"") && stdout.contains("glare grid \"seats\""), "{stdout}");
}

#[test]
fn an_observer_and_a_glare_grid_naming_a_grid_give_it_the_larger_of_theirs() {
    // "strong" looks at panel b from below it and afar; "none" looks away from both panels.
    let observers = "[[observer]]\nname = \"strong\"\nposition = [0.6, 1.6, 3.0]\nlook = [1, 0, 0]\ngrid = \"desk\"\n\
                     [[observer]]\nname = \"none\"\nposition = [3.5, 1.2, 2.0]\nlook = [1, 0, 0]\ngrid = \"bench\"\n";
    let text = room(4.0, 0.5, 0.0)
        + PANELS
        + &grid("desk", 40.0)
        + &grid("bench", 40.0)
        + &glare_grid("desks", "desk")
        + &glare_grid("seats", "bench")
        + observers;
    let (file, stdout) = solve("grid-ugr-both", &text);
    let observed = file.dataset("observers/ugr").unwrap().read_raw::<f64>().unwrap();
    for (k, (grid, glare)) in [("desk", "desks"), ("bench", "seats")].into_iter().enumerate() {
        let ugr = attr(&file, &format!("grids/{grid}"), "UGR");
        let largest = attr(&file, &format!("glare_grids/{glare}"), "UGR_max");
        let expected = observed[k].max(largest);
        assert!((ugr - expected).abs() < 1e-9, "{grid}: {ugr} against max({}, {largest})", observed[k]);
        assert_summary_line(&stdout, grid, ugr, 40.0);
    }
    assert!(observed[0] > attr(&file, "glare_grids/desks", "UGR_max"), "the observer's is the larger: {observed:?}");
    assert_eq!(observed[1], f64::NEG_INFINITY, "the glare grid's is the larger");
    assert!(stdout.contains("1 observer, glare grid \"desks\""), "{stdout}");
}

#[test]
fn a_glare_grids_grid_is_validated_and_satisfies_a_ugr_target() {
    let base = room(4.0, 0.5, 10.0) + &grid("desk", 19.0);
    let parse = |more: &str| Scene::parse(Path::new("cases/test.toml"), format!("{base}{more}"));
    let error = parse(&glare_grid("desks", "bench")).expect_err("a grid of no [[grid]]").to_string();
    let line = base.lines().count() + 9;
    for words in ["cases/test.toml", "[[glare_grid]] \"desks\" (#1)", "grid", "names no [[grid]]", "\"bench\""] {
        assert!(error.contains(words), "{words}: {error}");
    }
    assert!(error.contains(&format!("line {line}:")), "line {line}: {error}");
    let unread = parse("").expect_err("a `ugr` target nothing reads").to_string();
    for words in ["[[grid]] \"desk\" (#1)", "target", "needs an [[observer]] or a [[glare_grid]]", "grid = \"desk\""] {
        assert!(unread.contains(words), "{words}: {unread}");
    }
    let scene = parse(&glare_grid("desks", "desk")).unwrap_or_else(|e| panic!("{e}"));
    let g = &scene.glare_grids[0];
    assert_eq!(g.grid.as_deref(), Some("desk"));
    assert!(g.observers().iter().all(|o| o.grid.as_deref() == Some("desk")));
}

/// Under light scenes each scene's grid takes its UGR from that scene's glare grid: equal to
/// the scene's `UGR_max`, the dimmed scene's otherwise than the case's.
#[test]
fn each_light_scenes_grid_reads_that_scenes_glare_grid() {
    let scenes = "[[light_scene]]\nname = \"all\"\ngroups = { a = 1, b = 1 }\n\
                  [[light_scene]]\nname = \"half\"\ngroups = { a = 0.5, b = false }\n";
    let text = room(4.0, 0.5, 0.0) + PANELS + &grid("desk", 19.0) + &glare_grid("desks", "desk") + scenes;
    let (file, stdout) = solve("grid-ugr-scenes", &text);
    let mut read = Vec::new();
    for at in ["", "light_scenes/all/", "light_scenes/half/"] {
        let ugr = attr(&file, &format!("{at}grids/desk"), "UGR");
        let largest = attr(&file, &format!("{at}glare_grids/desks"), "UGR_max");
        assert!((ugr - largest).abs() < 1e-9, "{at}: {ugr} against {largest}");
        read.push(ugr);
    }
    assert!((read[0] - read[1]).abs() < 1e-6, "all on as the case: {read:?}");
    assert!((read[0] - read[2]).abs() > 0.1, "the dimmed scene reads otherwise: {read:?}");
    let half = stdout.split("light scene \"half\"").nth(1).expect("the scene is reported");
    assert_summary_line(half, "desk", read[2], 19.0);
}

/// `ugo readout` of a case whose glare grid names the grid after the solve (and whose grid
/// is given its `ugr` target then) writes the grid's UGR from the stored field.
#[test]
fn ugo_readout_reads_a_glare_grid_named_after_the_solve() {
    let dir = scratch("grid-ugr-readout");
    std::fs::write(dir.as_ref().join("panel.ies"), PANEL).expect("writable");
    let before = room(4.0, 0.5, 0.0) + PANELS + &grid("desk", 19.0).replace("target = { ugr = 19 }\n", "");
    let case =
        dir.write("case.toml", &(before.clone() + &glare_grid("desks", "desk").replace("grid = \"desk\"\n", "")));
    let edited = dir.write(
        "edited.toml",
        &(before.replace("normal = [0, 1, 0]\n", "normal = [0, 1, 0]\ntarget = { ugr = 19 }\n")
            + &glare_grid("desks", "desk")),
    );
    let out = dir.join("res.h5");
    let s = |p: &Path| p.to_str().unwrap().to_string();
    let o = ugo(&["solve", &s(&case), "--save-kernel", "-o", &s(&out)]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let file = hdf5::File::open(&out).unwrap();
    assert!(file.group("grids/desk").unwrap().attr("UGR").is_err(), "no UGR before the glare grid names the grid");
    drop(file);
    let o = ugo(&["readout", &s(&out), &s(&edited)]);
    let stdout = String::from_utf8_lossy(&o.stdout).into_owned();
    assert!(o.status.success(), "{stdout}{}", String::from_utf8_lossy(&o.stderr));
    let file = hdf5::File::open(&out).unwrap();
    let (ugr, largest) = (attr(&file, "grids/desk", "UGR"), attr(&file, "glare_grids/desks", "UGR_max"));
    assert!(ugr.is_finite() && (ugr - largest).abs() < 1e-9, "{ugr} against {largest}");
    assert_eq!(attr(&file, "grids/desk", "UGR_target"), 19.0);
    assert_summary_line(&stdout, "desk", ugr, 19.0);
}
