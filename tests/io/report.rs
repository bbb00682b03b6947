//! `ugo report` (docs/report.md): the daylit office, made small and given a luminaire, a
//! grid target, an observer, a glare grid feeding the grid's UGR and a light scene, solved; its case file removed; the page
//! checked by `report_check.py` (a strict HTML parse, every table row as long as its
//! header, every plan a PNG data: URI, no outside reference, the grid, luminaire,
//! daylight, glare, glare-grid, light-scene (their observers' UGR coloured against `UGR_L`), surface and
//! probe figures (with their error bars, in every light scene) equal to the HDF5 file's as shown);
//! `-o` and the default name; a file that is not a solution refused naming it; the furnace
//! box, which has none of the optional parts, reads 5π lx on every side of its room.

use crate::support::{scratch, ugo};
use std::path::Path;

/// `cases/daylit-office.toml` with a downlight in a group, the work plane's targets (its
/// `UGR_L` read by the glare grid that names it), an observer with a limit, a glare grid
/// and a light scene.
fn case(dir: &Path) -> std::path::PathBuf {
    let office = std::fs::read_to_string("cases/daylit-office.toml").unwrap();
    let extra = r#"
[[luminaire]]
name = "downlight"
type = "isotropic"
flux = 3000
position = [3.0, 2.9, 2.0]
group = "room"

[[observer]]
name = "at the door"
position = [0.5, 1.2, 2.0]
look = [1, 0, 0]
ugr_limit = 19

[[glare_grid]]
name = "seats"
origin = [1.0, 1.2, 1.0]
edge_u = [3, 0, 0]
edge_v = [0, 0, 2]
resolution = [3, 2]
look = [1, 0, 0]
view_step_deg = 90
ugr_limit = 19
grid = "work_plane"

[[light_scene]]
name = "dimmed"
groups = { room = 0.5 }
"#;
    let office =
        office.replace("resolution = [24, 16]", "resolution = [24, 16]\ntarget = { em = 500, u0 = 0.4, ugr = 19 }");
    let path = dir.join("office.toml");
    std::fs::write(&path, office + extra).unwrap();
    path
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

#[test]
fn the_report_of_a_daylit_office_parses_and_shows_the_files_figures() {
    let dir = scratch("report");
    let case = case(&dir);
    let out = dir.join("office.h5");
    let solve = ugo(&["solve", s(&case), "--patch-size", "0.5", "-o", s(&out)]);
    assert!(solve.status.success(), "{}", String::from_utf8_lossy(&solve.stderr));
    std::fs::remove_file(&case).unwrap();
    let report = ugo(&["report", s(&out)]);
    assert!(report.status.success(), "{}", String::from_utf8_lossy(&report.stderr));
    let page = dir.join("office.html");
    assert!(String::from_utf8_lossy(&report.stdout).contains(s(&page)));
    let python = std::process::Command::new("/usr/bin/python3")
        .args(["tests/io/report_check.py", s(&page), s(&out)])
        .output()
        .expect("/usr/bin/python3 runs (make deps installs python3-h5py)");
    let said = format!("{}{}", String::from_utf8_lossy(&python.stdout), String::from_utf8_lossy(&python.stderr));
    assert!(python.status.success(), "tests/io/report_check.py: {said}");
    // the work plane's UGR is the glare grid's largest (report_check.py derives it again)
    let file = hdf5::File::open(&out).unwrap();
    let attr = |g: &str, n: &str| file.group(g).unwrap().attr(n).unwrap().read_scalar::<f64>().unwrap();
    assert_eq!(attr("grids/work_plane", "UGR"), attr("glare_grids/seats", "UGR_max"));
    let tables = ["grids", "luminaires", "observers", "glare-grids", "glare-grid-1", "light-scenes", "daylight-grids"];
    for table in tables.into_iter().chain(["daylight-probes", "surfaces", "probes"]) {
        assert!(said.contains(table), "no table {table}: {said}");
    }
    let html = std::fs::read_to_string(&page).unwrap();
    // the grids' E_avg, E_min and U0 with their error bars (report_check.py checks each cell)
    assert!(html.contains(" ± "), "the grids' statistics show no error bar");
    let chosen = dir.join("chosen.html");
    let again = ugo(&["report", s(&out), "-o", s(&chosen)]);
    assert!(again.status.success(), "{}", String::from_utf8_lossy(&again.stderr));
    assert_eq!(std::fs::read(&chosen).unwrap(), html.into_bytes(), "the same page under the name -o gives");
}

#[test]
fn a_file_that_is_not_a_solution_is_refused_naming_it() {
    let dir = scratch("report-refused");
    let text = dir.join("notes.h5");
    std::fs::write(&text, "not HDF5").unwrap();
    let o = ugo(&["report", s(&text)]);
    let said = String::from_utf8_lossy(&o.stderr);
    assert!(!o.status.success() && said.contains("notes.h5"), "{said}");
    assert!(!dir.join("notes.html").exists(), "no page is written");
}

#[test]
fn the_furnace_box_has_no_optional_part_and_every_side_reads_five_pi_lux() {
    let dir = scratch("report-furnace");
    let out = dir.join("furnace.h5");
    let solve = ugo(&["solve", "cases/furnace-box.toml", "--patch-size", "0.25", "-o", s(&out)]);
    assert!(solve.status.success(), "{}", String::from_utf8_lossy(&solve.stderr));
    let page = dir.join("page.html");
    let report = ugo(&["report", s(&out), "-o", s(&page)]);
    assert!(report.status.success(), "{}", String::from_utf8_lossy(&report.stderr));
    let html = std::fs::read_to_string(&page).unwrap();
    for absent in ["luminaires", "grids", "glare", "glare-grids", "light-scenes", "daylight", "warnings"] {
        assert!(!html.contains(&format!("id=\"{absent}\"")), "a section {absent} in {html}");
    }
    assert!(!html.contains("<img"), "a plan without a grid");
    // 5 cd/m² arriving from every direction: E = 5π = 15.708 lx on each side of the room
    for side in ["up (floor)", "down (ceiling)", "vertical (wall)"] {
        let row = format!("<tr><td>room</td><td>grey</td><td>{side}</td>");
        let at = html.find(&row).unwrap_or_else(|| panic!("no row {row}"));
        let cells: Vec<&str> = html[at..].split("</tr>").next().unwrap().split("<td>").skip(5).collect();
        assert!(cells.iter().take(3).all(|c| c.starts_with("15.7<")), "{side}: {cells:?}");
    }
}
