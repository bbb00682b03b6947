//! `ugo solve --save-kernel` and `--kernel FILE.h5` (docs/kernel-file.md): the kernel
//! rebuilt by h5py and scipy alone reproduces ugo's solution, `K x` and exports to 1e-12
//! (`kernel_check.py`); a reloaded kernel gives the identical solution without assembly;
//! a changed geometry, discretization or precision is refused naming the part; a changed
//! reflectance or luminaire reuses `G` and equals a fresh solve; a hierarchical case is
//! refused a uniform file (`hierarchy_file.rs` saves and reuses the hierarchy).

use crate::support::{scratch, ugo};
use std::path::{Path, PathBuf};
use std::process::Output;

/// A closed room with a glossy (Phong) rug, a two-sided transmitting panel and a bulb, at
/// K = 4 cells, solved directly: every part of `/kernel` is exercised.
pub const ROOM: &str = r#"
[scene]
name = "kernel file room"
description = "a closed room with a glossy rug, a two-sided opal panel and a bulb"

[discretization]
patch_size = 0.5
directions = 4
kernel = "uniform"

[solver]
method = "direct"

[[material]]
name = "wall"
type = "lambert"
reflectance = 0.6

[[material]]
name = "rug"
type = "phong"
reflectance = 0.3
specular = 0.4
exponent = 20

[[material]]
name = "opal"
type = "lambert"
reflectance = 0.2
transmittance = 0.5

[[surface]]
name = "room"
shape = "box"
min = [0.0, 0.0, 0.0]
max = [2.0, 2.0, 2.0]
material = "wall"
inside = true

[[surface]]
name = "rug"
shape = "rectangle"
origin = [0.25, 0.01, 0.25]
edge_u = [0.0, 0.0, 1.5]
edge_v = [1.5, 0.0, 0.0]
material = "rug"
two_sided = true

[[surface]]
name = "panel"
shape = "rectangle"
origin = [0.5, 1.0, 0.5]
edge_u = [0.0, 0.0, 1.0]
edge_v = [1.0, 0.0, 0.0]
material = "opal"
two_sided = true

[[luminaire]]
name = "bulb"
type = "isotropic"
flux = 1000
position = [1.0, 1.6, 1.0]
"#;

/// `ROOM` (with `edit` applied) written into `dir` as `name`.
pub fn room(dir: &Path, name: &str, edit: impl Fn(&str) -> String) -> PathBuf {
    let case = dir.join(name);
    std::fs::write(&case, edit(ROOM)).unwrap();
    case
}

pub fn run(args: &[&str]) -> Output {
    let o = ugo(args);
    assert!(o.status.success(), "ugo {args:?}: {}", String::from_utf8_lossy(&o.stderr));
    o
}

fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

fn failure(o: &Output) -> String {
    let err = String::from_utf8_lossy(&o.stderr).into_owned();
    assert!(!o.status.success() && !err.contains("panicked"), "{err}");
    err
}

pub fn luminance(path: &Path) -> Vec<f64> {
    let file = hdf5::File::open(path).unwrap();
    file.dataset("field/luminance").unwrap().read_raw::<f64>().unwrap()
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

#[test]
fn python_rebuilds_the_kernel_and_reproduces_the_solution_and_the_exports() {
    let dir = scratch("kernel-python");
    let case = room(&dir, "room.toml", str::to_string);
    let out = dir.join("room.h5");
    run(&["solve", s(&case), "--save-kernel", "-o", s(&out)]);
    let exports = dir.join("exports");
    std::fs::create_dir_all(&exports).unwrap();
    run(&["export", s(&out), "--format", "mtx", "-o", s(&exports)]);
    run(&["export", s(&out), "--format", "petsc", "-o", s(&exports)]);
    let said = kernel_check(&out, &exports);
    assert!(said.contains("kernel_check: ok") && said.contains("K.petsc"), "{said}");
}

/// What `tests/io/kernel_check.py` says of the solution file `out` and its exports in
/// `exports` (it must succeed).
pub fn kernel_check(out: &Path, exports: &Path) -> String {
    let python = std::process::Command::new("/usr/bin/python3")
        .args(["tests/io/kernel_check.py", s(out), s(exports)])
        .output()
        .expect("/usr/bin/python3 runs (make deps installs python3-h5py and python3-scipy)");
    let said = format!("{}{}", stdout(&python), String::from_utf8_lossy(&python.stderr));
    assert!(python.status.success(), "tests/io/kernel_check.py (make deps installs h5py and scipy): {said}");
    said
}

#[test]
fn a_reloaded_kernel_is_not_assembled_and_gives_the_identical_solution() {
    let dir = scratch("kernel-reload");
    let case = room(&dir, "room.toml", str::to_string);
    let (saved, again) = (dir.join("saved.h5"), dir.join("again.h5"));
    run(&["solve", s(&case), "--save-kernel", "-o", s(&saved)]);
    let o = run(&["solve", s(&case), "--kernel-file", s(&saved), "-o", s(&again)]);
    assert!(stdout(&o).contains("not assembled"), "{}", stdout(&o));
    assert_eq!(luminance(&saved), luminance(&again), "the reloaded kernel's solution");
    // In single precision too: G is stored as it is held.
    let (single, single_again) = (dir.join("single.h5"), dir.join("single-again.h5"));
    run(&["solve", s(&case), "--precision", "f32", "--save-kernel", "-o", s(&single)]);
    run(&["solve", s(&case), "--precision", "f32", "--kernel-file", s(&single), "-o", s(&single_again)]);
    assert_eq!(luminance(&single), luminance(&single_again));
    // norms and compare take the kernel too.
    let o = run(&["norms", s(&case), "--kernel-file", s(&saved), "-o", s(&dir.join("norms.h5"))]);
    assert!(stdout(&o).contains("ρ(K)") && stdout(&o).contains("not assembled"), "{}", stdout(&o));
    let compare = ["compare", s(&case), "--kernel-file", s(&saved), "--methods", "gmres,direct"];
    let o = run(&[&compare[..], &["-o", s(&dir.join("c.h5")), "--plot", s(&dir.join("c.png"))]].concat());
    assert!(stdout(&o).contains("not assembled"), "{}", stdout(&o));
}

#[test]
fn a_changed_geometry_discretization_or_precision_is_refused_naming_the_part() {
    let dir = scratch("kernel-refused");
    let case = room(&dir, "room.toml", str::to_string);
    let saved = dir.join("saved.h5");
    run(&["solve", s(&case), "--save-kernel", "-o", s(&saved)]);
    let out = dir.join("refused.h5");
    let refused = |case: &Path, extra: &[&str]| {
        failure(&ugo(&[&["solve", s(case), "--kernel-file", s(&saved), "-o", s(&out)], extra].concat()))
    };
    let err = refused(&case, &["--patch-size", "0.25"]);
    assert!(err.contains("discretization (patch_size 0.5 m in the file, patch_size 0.25 m in the case)"), "{err}");
    let err = refused(&case, &["--directions", "8"]);
    assert!(err.contains("discretization") && err.contains("directions 4 in the file"), "{err}");
    let err = refused(&case, &["--precision", "f32"]);
    assert!(err.contains("discretization") && err.contains("G in f64 in the file"), "{err}");
    let moved = room(&dir, "moved.toml", |t| t.replace("origin = [0.5, 1.0, 0.5]", "origin = [0.5, 1.1, 0.5]"));
    let err = refused(&moved, &[]);
    assert!(err.contains("geometry") && !err.contains("discretization"), "{err}");
    // the hierarchical kernel is another discretization (tests/io/hierarchy_file.rs saves it)
    let hierarchical = refused(&case, &["--kernel", "hierarchical"]);
    assert!(hierarchical.contains("discretization") && hierarchical.contains("method Explicit"));
    assert!(!out.exists());
}

#[test]
fn a_changed_reflectance_or_luminaire_reuses_g_and_equals_a_fresh_solve() {
    let dir = scratch("kernel-reuse");
    let case = room(&dir, "room.toml", str::to_string);
    let saved = dir.join("saved.h5");
    run(&["solve", s(&case), "--save-kernel", "-o", s(&saved)]);
    type Edit = fn(&str) -> String;
    let edits: [(&str, Edit, &str); 2] = [
        ("paler.toml", |t| t.replace("reflectance = 0.6", "reflectance = 0.7"), "reflectances"),
        ("dimmer.toml", |t| t.replace("flux = 1000", "flux = 400"), "luminaires"),
    ];
    for (name, edit, part) in edits {
        let changed = room(&dir, name, edit);
        let (reused, fresh) = (dir.join(format!("{name}-reused.h5")), dir.join(format!("{name}-fresh.h5")));
        let o = run(&["solve", s(&changed), "--kernel-file", s(&saved), "-o", s(&reused)]);
        assert!(stdout(&o).contains(&format!("{part} (")) && stdout(&o).contains("G reused"), "{}", stdout(&o));
        run(&["solve", s(&changed), "-o", s(&fresh)]);
        let (a, b) = (luminance(&reused), luminance(&fresh));
        let scale = b.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        let worst = a.iter().zip(&b).fold(0.0f64, |m, (x, y)| m.max((x - y).abs())) / scale;
        assert!(worst <= 1e-12, "{part}: the reused G's solution differs from a fresh solve by {worst:e}");
        assert_ne!(a, luminance(&saved), "{part}: the change changed nothing");
    }
}
