//! The floors of `src/lib.rs` hold: no `use crate::…` (or inline `crate::…` path) points
//! from a module to one on a higher floor, no files import each other, directly or round a
//! longer loop, and no two modules of one floor import each other (through different
//! files, which no file circle shows). The floors are read from the list at the top of
//! `src/lib.rs`, so that list is the one source of truth; the binary (`main.rs`, `cli/`)
//! stands above it. The analyser is also run on small made-up trees with a known fault
//! each, so that it is seen to fail.

mod graph;
mod paths;

use graph::{Fault, analyse, imports};
use std::path::Path;

/// Every `.rs` file under `src/`, as (path relative to `src/`, text).
fn sources() -> Vec<(String, String)> {
    fn walk(dir: &Path, root: &Path, out: &mut Vec<(String, String)>) {
        let mut entries: Vec<_> = std::fs::read_dir(dir).expect("src/ is readable").flatten().collect();
        entries.sort_by_key(|e| e.path());
        for entry in entries {
            let path = entry.path();
            if path.is_dir() {
                walk(&path, root, out);
            } else if path.extension().is_some_and(|e| e == "rs") {
                let relative = path.strip_prefix(root).expect("under src/").to_string_lossy().replace('\\', "/");
                out.push((relative, std::fs::read_to_string(&path).expect("a readable source file")));
            }
        }
    }
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut out = Vec::new();
    walk(&root, &root, &mut out);
    out
}

#[test]
fn no_import_points_up_a_floor_and_no_files_import_each_other() {
    let faults = analyse(&sources());
    assert!(faults.is_empty(), "layering faults:\n{}", faults.iter().map(|f| format!("  {f}\n")).collect::<String>());
}

/// Imports between the two kernels, `kernel/uniform/` and `kernel/hierarchy/`, either way.
fn between_peers(sources: &[(String, String)]) -> Vec<(String, String)> {
    let (uniform, hierarchy) = ("kernel/uniform/", "kernel/hierarchy/");
    let crosses = |a: &str, b: &str| a.starts_with(uniform) && b.starts_with(hierarchy);
    imports(sources).into_iter().filter(|(from, to)| crosses(from, to) || crosses(to, from)).collect()
}

#[test]
fn the_uniform_and_the_hierarchical_kernel_never_import_each_other() {
    let crossing = between_peers(&sources());
    assert!(crossing.is_empty(), "imports between the kernels: {crossing:?}");
}

#[test]
fn an_import_between_the_kernels_is_found() {
    let lib = "//! 1. kernel: [`kernel`]\npub mod kernel;\n";
    let files = [
        ("lib.rs", lib),
        ("kernel/mod.rs", "pub mod hierarchy;\nmod uniform;\npub use uniform::assemble;\n"),
        ("kernel/uniform/mod.rs", "mod assembly;\npub use assembly::assemble;\n"),
        ("kernel/uniform/assembly.rs", "pub fn assemble() {}\n"),
        ("kernel/hierarchy/mod.rs", "mod link;\n"),
        ("kernel/hierarchy/link.rs", "use crate::kernel::assemble;\n"),
    ];
    let sources: Vec<(String, String)> = files.iter().map(|(p, t)| (p.to_string(), t.to_string())).collect();
    let crossing = between_peers(&sources);
    assert_eq!(crossing, [("kernel/hierarchy/link.rs".to_string(), "kernel/uniform/assembly.rs".to_string())]);
}

/// A made-up crate: `lib.rs` with two floors, and the given files.
fn made_up(files: &[(&str, &str)]) -> Vec<Fault> {
    let lib = "//! 1. low: [`low`]\n//! 2. high: [`high`]\npub mod low;\npub mod high;\n";
    let mut all = vec![("lib.rs".to_string(), lib.to_string())];
    all.extend(files.iter().map(|(p, t)| (p.to_string(), t.to_string())));
    analyse(&all)
}

#[test]
fn an_import_up_a_floor_is_found() {
    let faults =
        made_up(&[("low.rs", "use crate::high::Thing;\npub struct Low;\n"), ("high.rs", "pub struct Thing;\n")]);
    assert!(
        matches!(faults.as_slice(), [Fault::Up { from, to, .. }] if from == "low.rs" && to == "high"),
        "{faults:?}"
    );
}

#[test]
fn an_inline_path_up_a_floor_is_found() {
    let faults = made_up(&[("low.rs", "fn f() { crate::high::go(); }\n"), ("high.rs", "pub fn go() {}\n")]);
    assert!(matches!(faults.as_slice(), [Fault::Up { .. }]), "{faults:?}");
}

#[test]
fn files_importing_each_other_through_a_parent_re_export_are_found() {
    let faults = made_up(&[
        ("high/mod.rs", "mod a;\nmod b;\npub use a::A;\npub use b::B;\n"),
        ("high/a.rs", "use super::B;\npub struct A;\n"),
        ("high/b.rs", "use super::A;\npub struct B;\n"),
        ("low.rs", "pub struct Low;\n"),
    ]);
    assert!(
        matches!(faults.as_slice(), [Fault::Circle(files)] if files.len() == 2 && files.contains(&"high/a.rs".to_string())),
        "{faults:?}"
    );
}

#[test]
fn modules_of_one_floor_importing_each_other_through_different_files_are_found() {
    let lib = "//! 1. pictures and paths: [`render`], [`trace`]\npub mod render;\npub mod trace;\n";
    let files = [
        ("lib.rs", lib),
        ("render/mod.rs", "mod image;\nmod lit;\npub use image::Image;\n"),
        ("render/image.rs", "pub struct Image;\n"),
        ("render/lit.rs", "use crate::trace::openings::Openings;\n"),
        ("trace/mod.rs", "pub mod camera;\npub mod openings;\n"),
        ("trace/camera.rs", "use crate::render::Image;\n"),
        ("trace/openings.rs", "pub struct Openings;\n"),
    ];
    let sources: Vec<(String, String)> = files.iter().map(|(p, t)| (p.to_string(), t.to_string())).collect();
    let faults = analyse(&sources);
    assert!(
        matches!(faults.as_slice(), [Fault::ModuleCircle(m)] if *m == ["render".to_string(), "trace".to_string()]),
        "{faults:?}"
    );
}

#[test]
fn a_binary_and_its_modules_importing_each_other_are_found() {
    let faults = made_up(&[
        ("main.rs", "mod cli;\npub struct Options;\nfn main() { cli::run(); }\n"),
        ("cli/mod.rs", "use crate::Options;\npub fn run() {}\n"),
        ("low.rs", ""),
        ("high.rs", ""),
    ]);
    assert!(matches!(faults.as_slice(), [Fault::Circle(files)] if files.len() == 2), "{faults:?}");
}

#[test]
fn a_module_without_a_floor_is_found() {
    let lib = "//! 1. low: [`low`]\npub mod low;\npub mod stray;\n";
    let files = vec![
        ("lib.rs".to_string(), lib.to_string()),
        ("low.rs".to_string(), String::new()),
        ("stray.rs".to_string(), String::new()),
    ];
    assert!(matches!(analyse(&files).as_slice(), [Fault::NoFloor(m)] if m == "stray"));
}

#[test]
fn downward_and_same_floor_imports_pass() {
    let faults = made_up(&[
        ("low.rs", "pub struct Low;\n"),
        ("high/mod.rs", "mod a;\nmod b;\npub use a::A;\n"),
        ("high/a.rs", "use crate::low::Low;\nuse super::b::helper;\npub struct A(Low);\n"),
        ("high/b.rs", "// use crate::high::A; in a comment does not count\npub fn helper() {}\n"),
    ]);
    assert!(faults.is_empty(), "{faults:?}");
}
