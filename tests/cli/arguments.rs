//! Command lines refused for the right reason (issue 18, items 5, 7 and 9): negative
//! numbers reach the option's own rule, limits on `--method gmres:M` and `--orders`,
//! the output checked before the work, and luminaire-only scenes traced.

use super::{assert_clean_failure, stderr};
use crate::support::{scratch, ugo};

#[test]
fn negative_numbers_are_refused_by_the_rule_of_their_option() {
    let case = "cases/furnace-box.toml";
    let err = assert_clean_failure(&ugo(&["solve", case, "--tolerance", "-1"]));
    assert!(err.contains("--tolerance must lie in (0, 1), got -1"), "{err}");
    let err = assert_clean_failure(&ugo(&["solve", case, "--patch-size", "-0.1"]));
    assert!(err.contains("--patch-size must be a length in metres greater than 0, got -0.1"), "{err}");
    let err = assert_clean_failure(&ugo(&["info", case, "--memory-limit", "-2"]));
    assert!(err.contains("--memory-limit must be a number of GiB greater than 0, got -2"), "{err}");
    // Unsigned options: clap's message names the option instead of "unexpected argument".
    let o = ugo(&["solve", case, "--max-iterations", "-1"]);
    assert!(!o.status.success());
    assert!(stderr(&o).contains("'--max-iterations <MAX_ITERATIONS>'"), "{}", stderr(&o));
}

#[test]
fn trace_accepts_a_scene_lit_only_by_luminaires() {
    let dir = scratch("trace-luminaires");
    let out = dir.join("forward.h5");
    let case = "cases/cie171/5.2-point-source.toml";
    let o = ugo(&["trace", case, "--forward", "--photons", "2000", "-o", out.to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    let emitted: f64 =
        hdf5::File::open(&out).unwrap().group("trace").unwrap().attr("emitted_flux").unwrap().read_scalar().unwrap();
    assert!(emitted > 0.0, "the luminaires' flux counts as emitted: {emitted}");
    let o = ugo(&["trace", case, "--probe-samples", "64"]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(String::from_utf8_lossy(&o.stdout).contains("probes"));
}

#[test]
fn an_output_that_cannot_be_written_is_refused_before_the_work() {
    let dir = scratch("unwritable");
    let missing = dir.join("no-such-folder").join("res.h5");
    // The Cornell box takes seconds to solve: the refusal must come before that.
    let start = std::time::Instant::now();
    let err = assert_clean_failure(&ugo(&["solve", "cases/cornell-box.toml", "-o", missing.to_str().unwrap()]));
    assert!(err.contains("does not exist") && err.contains("no-such-folder"), "{err}");
    assert!(start.elapsed().as_secs_f64() < 2.0, "refused after {:?}", start.elapsed());
    let err = assert_clean_failure(&ugo(&["solve", "cases/cornell-box.toml", "-o", dir.to_str().unwrap()]));
    assert!(err.contains("it is a folder"), "{err}");
    let plot = dir.join("nowhere").join("p.png");
    let o = ugo(&[
        "compare",
        "cases/cornell-box.toml",
        "--plot",
        plot.to_str().unwrap(),
        "-o",
        dir.join("c.h5").to_str().unwrap(),
    ]);
    let err = assert_clean_failure(&o);
    assert!(err.contains("nowhere"), "{err}");
    let left: Vec<_> = std::fs::read_dir(&dir).unwrap().map(|e| e.unwrap().file_name()).collect();
    assert!(left.iter().all(|n| !n.to_string_lossy().contains(".tmp")), "{left:?}");
}

#[test]
fn warnings_go_to_stderr_and_the_work_goes_on() {
    let dir = scratch("warning");
    let case = dir.join("bright.toml");
    let text = std::fs::read_to_string("cases/furnace-box.toml").unwrap();
    let bright = text.replacen("luminance = 1.0", "luminance = 1e10", 1);
    assert_ne!(text, bright);
    std::fs::write(&case, bright).unwrap();
    let o = ugo(&["info", case.to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    let err = stderr(&o);
    assert!(err.starts_with("ugo: warning: ") && err.contains("emission.luminance"), "{err}");
}

#[test]
fn solver_sizes_from_the_command_line_are_limited() {
    let case = "cases/furnace-box.toml";
    let o = ugo(&["solve", case, "--method", "gmres:100000000000"]);
    assert!(!o.status.success());
    assert!(stderr(&o).contains("M must lie in 1..=1000"), "{}", stderr(&o));
    let o = ugo(&["solve", case, "--orders", "18446744073709551615"]);
    assert!(!o.status.success());
    assert!(stderr(&o).contains("at most 100000 reflections"), "{}", stderr(&o));
    let many: Vec<String> = (1..=65).map(|n| n.to_string()).collect();
    let err = assert_clean_failure(&ugo(&["solve", case, "--orders", &many.join(",")]));
    assert!(err.contains("at most 64 orders"), "{err}");
}

#[test]
fn a_named_pipe_or_invalid_text_is_refused_without_blocking() {
    let dir = scratch("pipe");
    let pipe = dir.join("case.toml");
    let _ = std::fs::remove_file(&pipe);
    assert!(std::process::Command::new("mkfifo").arg(&pipe).status().unwrap().success());
    // Each would block forever on opening the pipe for reading.
    for args in [vec!["info", pipe.to_str().unwrap()], vec!["render", pipe.to_str().unwrap()]] {
        let err = assert_clean_failure(&ugo(&args));
        assert!(err.contains("not a regular file"), "{err}");
    }
    let bad = dir.join("latin1.toml");
    std::fs::write(&bad, b"[scene]\nname = \"caf\xe9\"\n").unwrap();
    let err = assert_clean_failure(&ugo(&["info", bad.to_str().unwrap()]));
    assert!(err.contains("line 2: not UTF-8 text (byte 0xe9 at column 12)"), "{err}");
}

#[test]
fn a_model_over_the_memory_limit_is_refused_before_meshing_with_its_estimate() {
    // bench too: it meshed without the forecast once.
    let case = "cases/furnace-box.toml";
    for command in ["info", "solve", "bench"] {
        let started = std::time::Instant::now();
        let err = assert_clean_failure(&ugo(&[command, case, "--patch-size", "1e-12", "--kernel", "uniform"]));
        assert!(started.elapsed().as_secs_f64() < 5.0, "{command}: {:?}", started.elapsed());
        for fragment in ["6.000e24 patches", "facing pairs", "estimated before meshing", "--kernel hierarchical"] {
            assert!(err.contains(fragment), "{command}: {err}");
        }
        // chosen by size, the hierarchy, and its roots (4e-12 m) are refused
        let err = assert_clean_failure(&ugo(&[command, case, "--patch-size", "1e-12", "--kernel", "auto"]));
        for fragment in ["3.750e23 patches", "roots of the hierarchy", "estimated before meshing"] {
            assert!(err.contains(fragment), "{command}: {err}");
        }
        assert!(!err.contains("--kernel hierarchical") && err.contains("--root-size"), "{command}: {err}");
    }
    // the forecast before the refusal, in figures that fit its column
    let o = ugo(&["info", case, "--patch-size", "1e-12", "--kernel", "auto"]);
    let out = String::from_utf8_lossy(&o.stdout);
    assert!(out.contains("memory before links 3.185e17 GiB"), "{out}");
    // info prints the forecast before it refuses, and the forecast of a model that fits.
    let o = ugo(&["info", case]);
    let out = String::from_utf8_lossy(&o.stdout);
    assert!(out.contains("before meshing") && out.contains("memory at peak"), "{out}");
    let o = ugo(&["info", case, "--kernel", "hierarchical", "--root-size", "0.1", "--patch-size", "0.001"]);
    let out = String::from_utf8_lossy(&o.stdout);
    assert!(out.contains("leaves at most") && out.contains("2.400e7"), "{out}");
    assert!(out.contains("memory before links") && !out.contains("memory at peak"), "{out}");
}

#[test]
fn an_obj_model_in_millimetres_is_warned_about_and_refused_before_meshing() {
    // A 5,000 × 3,000 × 4,000 mm room drawn in millimetres, read as metres: 13.5 GB before.
    let dir = scratch("millimetres");
    let mut obj = String::new();
    for [x, y, z] in [[0, 0, 0], [5000, 0, 0], [5000, 0, 4000], [0, 0, 4000], [0, 3000, 0], [5000, 3000, 0]] {
        obj += &format!("v {x} {y} {z}\n");
    }
    obj += "f 1 3 2\nf 1 4 3\nf 1 2 6\nf 1 6 5\n";
    std::fs::write(dir.join("room.obj"), obj).unwrap();
    let text =
        std::fs::read_to_string("cases/furnace-box.toml").unwrap().replace("kernel = \"uniform\"", "kernel = \"auto\"")
            + "\n[[surface]]\nname = \"model\"\nshape = \"mesh\"\nfile = \"room.obj\"\nmaterial = \"grey\"\n";
    let case = dir.join("mm.toml");
    std::fs::write(&case, text).unwrap();
    let started = std::time::Instant::now();
    let err = assert_clean_failure(&ugo(&["info", case.to_str().unwrap()]));
    assert!(started.elapsed().as_secs_f64() < 5.0, "{:?}", started.elapsed());
    assert!(err.starts_with("ugo: warning: ") && err.contains("scale = 0.001"), "{err}");
    assert!(
        err.contains("mm.toml at [discretization] patch_size = 0.1 m, [discretization] root_size = 0.4 m: "),
        "{err}"
    );
    assert!(err.contains(": the model would need") && err.contains("patches"), "{err}");
}

#[test]
fn physics_warnings_reach_stderr_the_summary_and_the_file_and_strict_makes_them_errors() {
    let dir = scratch("physics-warnings");
    let case = dir.join("probe-down.toml");
    let text = std::fs::read_to_string("cases/furnace-box.toml").unwrap();
    let down = text.replacen(
        "position = [0.5, 0.0, 0.5]\nnormal = [0.0, 1.0, 0.0]",
        "position = [0.5, 0.0, 0.5]\nnormal = [0.0, -1.0, 0.0]",
        1,
    );
    assert_ne!(text, down);
    std::fs::write(&case, down).unwrap();
    let out = dir.join("res.h5");
    let args =
        ["solve", case.to_str().unwrap(), "--patch-size", "0.25", "--kernel", "uniform", "-o", out.to_str().unwrap()];
    let o = ugo(&args);
    assert!(o.status.success(), "{}", stderr(&o));
    let err = stderr(&o);
    assert!(err.contains("ugo: warning: probe \"floor centre\": its normal points into the surface"), "{err}");
    assert!(String::from_utf8_lossy(&o.stdout).contains("warnings                      1"));
    let file = hdf5::File::open(&out).unwrap();
    let stored: Vec<hdf5::types::VarLenUnicode> = file.dataset("warnings").unwrap().read_raw().unwrap();
    assert_eq!(stored.len(), 1);
    assert!(stored[0].as_str().contains("floor centre"));
    drop(file);
    std::fs::remove_file(&out).unwrap();
    let err = assert_clean_failure(&ugo(&[&args[..], &["--strict"]].concat()));
    assert!(err.contains("--strict") && err.contains("floor centre"), "{err}");
    assert!(!out.exists(), "--strict wrote the file");
}

/// An OBJ model's triangles are each a patch at any size: its refusal says that a larger
/// size cannot help and names what can (issue 37, point 7: a 2·10⁶-triangle OBJ).
#[test]
fn a_model_of_too_many_triangles_is_told_to_simplify_not_to_coarsen() {
    let dir = crate::support::scratch("triangles");
    let n = 100;
    let mut obj = String::new();
    for i in 0..=n {
        for j in 0..=n {
            obj += &format!("v {} 0.5 {}\n", i as f64 * 0.04, j as f64 * 0.04);
        }
    }
    for i in 0..n {
        for j in 0..n {
            let (a, c) = (i * (n + 1) + j + 1, (i + 1) * (n + 1) + j + 1);
            obj += &format!("f {a} {c} {}\nf {} {c} {}\n", a + 1, a + 1, c + 1);
        }
    }
    dir.write("sheet.obj", &obj);
    let case = dir.write(
        "case.toml",
        "[discretization]\npatch_size = 0.5\n\n[[material]]\nname = \"grey\"\ntype = \"lambert\"\nreflectance = 0.5\n\n\
         [[surface]]\nname = \"room\"\nshape = \"box\"\nmin = [0, 0, 0]\nmax = [4, 3, 4]\ninside = true\n\
         material = \"grey\"\nemission = { luminance = 1.0 }\n\n\
         [[surface]]\nname = \"sheet\"\nshape = \"mesh\"\nfile = \"sheet.obj\"\nmaterial = \"grey\"\n",
    );
    let case = case.to_str().unwrap();
    for kernel in ["uniform", "hierarchical"] {
        let err = assert_clean_failure(&ugo(&["solve", case, "--kernel", kernel, "--memory-limit", "0.001"]));
        for fragment in ["2.001e4 of the ", "patches are the surfaces' own elements", "simplify the models"] {
            assert!(err.contains(fragment), "{kernel}: {err}");
        }
        assert!(!err.contains("a larger --patch-size") && !err.contains("a larger --root-size"), "{kernel}: {err}");
        assert_eq!(err.contains("--kernel hierarchical"), kernel == "uniform", "{kernel}: {err}");
    }
    // a room alone at a small patch size still hears of the patch size
    let err =
        assert_clean_failure(&ugo(&["solve", "cases/furnace-box.toml", "--patch-size", "1e-4", "--kernel", "uniform"]));
    assert!(err.contains("a larger --patch-size") && !err.contains("simplify the models"), "{err}");
}
