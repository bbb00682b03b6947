//! `ugo readout` (issue 38, point 2; `docs/light-scenes.md`, "After the solve"): a light
//! scene and a probe added to a solved case and read on its stored field equal the same
//! scene and probe solved with the case, on the uniform and the hierarchical kernel; the
//! file is replaced whole or written beside; a light scene added alone leaves every stored
//! reading as it was (not read again), and the groups' stored direct light reads it as
//! their light traced again does (a file solved before it was stored); a changed geometry,
//! a light scene lighting a group the file does not hold and a file without its kernel are
//! refused, the file left as it was; under daylight alone, a probe and a grid added read
//! their daylight factors as a solve does, and with a lamp beside the sky they are refused.
//! (`group_by`'s groups: `tests/scene/luminaire_arrays.rs`.)

use super::light_scenes::CASE;
use super::{assert_clean_failure, stderr};
use crate::support::{scratch, ugo};
use std::path::Path;

/// The light scene added after the solve.
const THIRD: &str = r#"
[[light_scene]]
name = "third"
groups = { default = 0.3, ceiling = 0.6 }
"#;

/// The light scene and the probe added after the solve.
const ADDED: &str = r#"
[[light_scene]]
name = "third"
groups = { default = 0.3, ceiling = 0.6 }

[[probe]]
name = "wall"
position = [0, 1, 1]
normal = [1, 0, 0]
"#;

fn run(args: &[&str]) -> String {
    let o = ugo(args);
    assert!(o.status.success(), "{args:?}: {}", stderr(&o));
    String::from_utf8_lossy(&o.stdout).into_owned()
}

fn read(file: &Path, name: &str) -> Vec<f64> {
    hdf5::File::open(file).unwrap().dataset(name).unwrap().read_raw::<f64>().unwrap()
}

/// Largest difference of `a` from `b` relative to the largest `|b|`.
fn relative(a: &[f64], b: &[f64]) -> f64 {
    assert_eq!(a.len(), b.len());
    let scale = b.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    a.iter().zip(b).fold(0.0f64, |m, (x, y)| m.max((x - y).abs())) / scale
}

#[test]
fn a_light_scene_and_a_probe_read_after_the_solve_equal_them_solved() {
    for (name, kernel) in [("uniform", "uniform"), ("hierarchical", "hierarchical")] {
        let dir = scratch(&format!("readout-{name}"));
        let case = dir
            .write("box.toml", &CASE.replace("patch_size = 0.5", &format!("patch_size = 0.5\nkernel = \"{kernel}\"")));
        let edited = dir.write("box3.toml", &format!("{}{ADDED}", std::fs::read_to_string(&case).unwrap()));
        let (case, edited) = (case.to_str().unwrap(), edited.to_str().unwrap());
        let (solved, read_out, both) = (dir.join("a.h5"), dir.join("b.h5"), dir.join("c.h5"));
        let (a, b, c) = (solved.to_str().unwrap(), read_out.to_str().unwrap(), both.to_str().unwrap());
        run(&["solve", case, "--save-kernel", "-o", a]);
        let before = std::fs::read(&solved).unwrap();
        let summary = run(&["readout", a, edited, "-o", b]);
        assert!(summary.contains("light scene \"third\"") && dir.join("b-third-probes.csv").exists(), "{summary}");
        assert_eq!(std::fs::read(&solved).unwrap(), before, "{name}: -o changed the input");
        // The same case solved with the scene and probe (on the hierarchy the file refined).
        match kernel {
            "uniform" => run(&["solve", edited, "-o", c]),
            _ => run(&["solve", edited, "--kernel-file", a, "-o", c]),
        };
        for scene in ["night", "full", "third"] {
            let at = |what: &str| format!("light_scenes/{scene}/{what}");
            let field = relative(&read(&read_out, &at("field/luminance")), &read(&both, &at("field/luminance")));
            assert!(field <= 1e-10, "{name}: {scene}: field {field:e}");
            for what in ["probes/illuminance", "grids/desk/illuminance"] {
                let d = relative(&read(&read_out, &at(what)), &read(&both, &at(what)));
                assert!(d <= 1e-12, "{name}: {scene}: {what} {d:e}");
            }
        }
        let probes = (read(&read_out, "probes/illuminance"), read(&both, "probes/illuminance"));
        assert_eq!(probes.0.len(), 2);
        assert!(relative(&probes.0, &probes.1) <= 1e-12, "{name}: {probes:?}");

        // Without -o the file itself is replaced, and reads as a solve's.
        run(&["readout", a, edited]);
        assert_eq!(
            read(&solved, "light_scenes/third/field/luminance"),
            read(&read_out, "light_scenes/third/field/luminance")
        );
        run(&["report", a]);
        run(&["render", a, "--light-scene", "third", "-o", dir.to_str().unwrap()]);
    }
}

/// A block standing on the floor: the floor's patches under it are partly covered (their
/// exposed areas, which the energy balance weighs, are measured again around the kernel).
const BLOCK: &str = r#"
[[surface]]
name = "block"
shape = "box"
material = "grey"
min = [1.3, 0, 1.3]
max = [1.8, 0.4, 1.8]
"#;

#[test]
fn a_light_scene_added_alone_keeps_the_stored_readings_and_reads_the_stored_direct_light_as_traced() {
    let dir = scratch("readout-kept");
    let case = dir.write("box.toml", &format!("{CASE}{BLOCK}"));
    let edited = dir.write("box3.toml", &format!("{CASE}{BLOCK}{THIRD}"));
    let (solved, read_out, traced) = (dir.join("a.h5"), dir.join("b.h5"), dir.join("c.h5"));
    let (a, b, c) = (solved.to_str().unwrap(), read_out.to_str().unwrap(), traced.to_str().unwrap());
    let edited = edited.to_str().unwrap();
    run(&["solve", case.to_str().unwrap(), "--save-kernel", "-o", a]);
    let summary = run(&["readout", a, edited, "-o", b]);
    assert!(summary.contains("light scene \"full\" as stored") && summary.contains("observers as stored"), "{summary}");
    assert!(summary.contains("light scene \"third\"") && !summary.contains("traced again"), "{summary}");
    let mut kept: Vec<String> =
        ["probes/illuminance", "grids/desk/illuminance", "grids/desk/error"].map(String::from).into();
    for scene in ["night", "full"] {
        let at = ["field/illuminance", "probes/illuminance", "grids/desk/error"]
            .map(|w| format!("light_scenes/{scene}/{w}"));
        kept.extend(at);
    }
    let bits = |file: &Path, name: &str| read(file, name).iter().map(|v| v.to_bits()).collect::<Vec<u64>>();
    for name in &kept {
        assert_eq!(bits(&read_out, name), bits(&solved, name), "{name} was read again");
    }
    // Its energy balance is the solve's (each patch's exposed area as the solve measured it).
    let both = dir.join("d.h5");
    run(&["solve", edited, "-o", both.to_str().unwrap()]);
    let flux = |file: &Path| -> f64 {
        let g = hdf5::File::open(file).unwrap().group("light_scenes/third").unwrap();
        g.attr("flux_absorbed").unwrap().read_scalar().unwrap()
    };
    let (ours, theirs) = (flux(&read_out), flux(&both));
    assert!((ours - theirs).abs() <= 1e-10 * theirs, "absorbed {ours} lm, solved {theirs} lm");
    // The file as a solve wrote it before the groups' direct light was stored.
    let older = dir.join("older.h5");
    std::fs::copy(&solved, &older).unwrap();
    let file = hdf5::File::open_rw(&older).unwrap();
    ["light_groups/direct", "light_groups/intercepted"].into_iter().for_each(|name| file.unlink(name).unwrap());
    file.close().unwrap();
    let summary = run(&["readout", older.to_str().unwrap(), edited, "-o", c]);
    assert!(summary.contains("no /light_groups/direct") && summary.contains("traced again default"), "{summary}");
    for what in ["field/luminance", "field/direct_illuminance", "probes/illuminance", "grids/desk/illuminance"] {
        let at = format!("light_scenes/third/{what}");
        let d = relative(&read(&read_out, &at), &read(&traced, &at));
        assert!(d <= 1e-12, "{what}: stored against traced {d:e}");
    }
}

#[test]
fn a_hierarchy_with_an_emitting_surface_that_reflects_nothing_reads_out_after_the_solve() {
    // The open box's lamp is a surface of albedo 0: its leaves' cut limits are +∞
    // (`model/hierarchical.rs`, `worth_cutting`), which the kernel file stores and which
    // `ugo readout` refused as not finite (`tools/accuracy/bench.py --step unsteered open-box`).
    let dir = scratch("readout-black-lamp");
    let (solved, read_out) = (dir.join("a.h5"), dir.join("b.h5"));
    let (a, b) = (solved.to_str().unwrap(), read_out.to_str().unwrap());
    run(&["solve", "cases/open-box.toml", "--save-kernel", "-o", a]);
    let least = read(&solved, "kernel/direct/least");
    assert!(least.iter().any(|x| x.is_infinite()), "no leaf with an infinite cut limit");
    run(&["readout", a, "cases/open-box.toml", "-o", b]);
    let (again, stored) = (read(&read_out, "probes/illuminance"), read(&solved, "probes/illuminance"));
    assert!(!stored.is_empty() && relative(&again, &stored) <= 1e-12, "{again:?} against {stored:?}");
}

#[test]
fn a_changed_case_is_refused_and_the_file_left_as_it_was() {
    let dir = scratch("readout-refused");
    let case = dir.write("box.toml", CASE);
    let out = dir.join("a.h5");
    let a = out.to_str().unwrap();
    run(&["solve", case.to_str().unwrap(), "--save-kernel", "-o", a]);
    let before = std::fs::read(&out).unwrap();
    let refused = |text: &str, file: &str| {
        let edited = dir.write("edited.toml", text);
        let err = assert_clean_failure(&ugo(&["readout", file, edited.to_str().unwrap()]));
        assert_eq!(std::fs::read(&out).unwrap(), before, "the file changed: {err}");
        err
    };
    let err = refused(&CASE.replace("max = [2, 2, 2]", "max = [2, 2, 2.5]"), a);
    assert!(err.contains("geometry") && err.contains("not reused"), "{err}");
    let err = refused(&CASE.replace("ceiling", "lamp"), a);
    assert!(
        err.contains("\"full\"") && err.contains("group \"lamp\"") && err.contains("\"ceiling\", \"default\""),
        "{err}"
    );
    let err = refused(&CASE.replace("flux = 300", "flux = 400"), a);
    assert!(err.contains("\"lamp\"") && err.contains("emits"), "{err}");

    let plain = dir.join("plain.h5");
    run(&["solve", case.to_str().unwrap(), "-o", plain.to_str().unwrap()]);
    let err = assert_clean_failure(&ugo(&["readout", plain.to_str().unwrap(), case.to_str().unwrap()]));
    assert!(err.contains("--save-kernel"), "{err}");
}

/// A 1 × 1 m floor (ρ 0.5) and a 1 × 1 m wall beside it under a 1 × 1 m roof opening 1 m
/// up, the uniform sky: a case lit by daylight alone.
const DAYLIT: &str = r#"
[discretization]
patch_size = 0.25
kernel = "uniform"
[[material]]
name = "white"
type = "lambert"
reflectance = 0.5
[[surface]]
name = "floor"
shape = "rectangle"
material = "white"
origin = [0, 0, 0]
edge_u = [0, 0, 1]
edge_v = [1, 0, 0]
[[surface]]
name = "wall"
shape = "rectangle"
material = "white"
origin = [0, 0, 0]
edge_u = [0, 1, 0]
edge_v = [0, 0, 1]
[sky]
type = "uniform"
[[window]]
name = "roof"
origin = [0, 1, 0]
edge_u = [1, 0, 0]
edge_v = [0, 0, 1]
[[probe]]
name = "floor"
position = [0.5, 0, 0.5]
normal = [0, 1, 0]
"#;

/// What is added after the solve: a probe on the wall and a grid over the floor.
const DAYLIT_READINGS: &str = r#"
[[probe]]
name = "wall"
position = [0, 0.3, 0.5]
normal = [1, 0, 0]
[[grid]]
name = "plane"
origin = [0.1, 0.2, 0.1]
edge_u = [0.8, 0, 0]
edge_v = [0, 0, 0.8]
resolution = [3, 2]
normal = [0, 1, 0]
"#;

#[test]
fn a_probe_and_a_grid_added_under_daylight_alone_read_their_daylight_factors_as_solved() {
    let dir = scratch("readout-daylight");
    let case = dir.write("roof.toml", DAYLIT);
    let edited = dir.write("roof2.toml", &format!("{DAYLIT}{DAYLIT_READINGS}"));
    let (case, edited) = (case.to_str().unwrap(), edited.to_str().unwrap());
    let (solved, read_out, both) = (dir.join("a.h5"), dir.join("b.h5"), dir.join("c.h5"));
    let (a, b, c) = (solved.to_str().unwrap(), read_out.to_str().unwrap(), both.to_str().unwrap());
    run(&["solve", case, "--save-kernel", "-o", a]);
    let summary = run(&["readout", a, edited, "-o", b]);
    run(&["solve", edited, "-o", c]);
    assert!(summary.contains("daylight"), "{summary}");
    for what in ["sky_component", "internally_reflected", "daylight_factor"] {
        let (probes, grid) = (format!("daylight/probes/{what}"), format!("daylight/grids/plane/{what}"));
        let (x, y) = (read(&read_out, &probes), read(&both, &probes));
        assert!(x.len() == 2 && y[1] > 0.0 && relative(&x, &y) <= 1e-12, "{what}: {x:?} against {y:?}");
        let (x, y) = (read(&read_out, &grid), read(&both, &grid));
        assert!(x.len() == 6 && relative(&x, &y) <= 1e-12, "{what}: {x:?} against {y:?}");
    }
    let csv = std::fs::read_to_string(dir.join("b-probes.csv")).unwrap();
    assert!(csv.lines().next().unwrap().ends_with("DF_pct"), "{csv}");

    // With a lamp beside the sky the daylight would need a solve of its own: refused, the
    // file left as it was.
    let lamp = "[[luminaire]]\nname = \"bulb\"\ntype = \"isotropic\"\nflux = 100\nposition = [0.5, 0.5, 0.5]\n";
    let lit = dir.write("lit.toml", &format!("{DAYLIT}{lamp}"));
    let lit_edited = dir.write("lit2.toml", &format!("{DAYLIT}{lamp}{DAYLIT_READINGS}"));
    run(&["solve", lit.to_str().unwrap(), "--save-kernel", "-o", a]);
    let before = std::fs::read(&solved).unwrap();
    let err = assert_clean_failure(&ugo(&["readout", a, lit_edited.to_str().unwrap()]));
    assert!(err.contains("beside other light") && err.contains("solved alone"), "{err}");
    assert_eq!(std::fs::read(&solved).unwrap(), before, "the file changed: {err}");
}
