//! Every file a command writes goes beside the output it was given, and its summary names
//! each one (issue 17, item 5).

use super::stderr;
use crate::support::{scratch, ugo};

#[test]
fn compare_writes_its_plot_beside_its_output_and_lists_every_file() {
    let base = scratch("beside");
    let dir = base.join("results");
    std::fs::create_dir_all(&dir).unwrap();
    let out = dir.join("x.h5");
    let case = "cases/furnace-box.toml";
    let o = ugo(&["compare", case, "--patch-size", "0.5", "--methods", "neumann,gmres", "-o", out.to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    let summary = String::from_utf8_lossy(&o.stdout);
    let mut written: Vec<String> =
        std::fs::read_dir(&dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
    written.sort();
    assert_eq!(written, ["x-probes.csv", "x.h5", "x.png"], "{summary}");
    for name in &written {
        assert!(summary.contains(dir.join(name).to_str().unwrap()), "{name} is not listed:\n{summary}");
    }
    assert!(!std::path::Path::new("furnace-box-compare.png").exists(), "a plot in the current folder");
}

#[test]
fn a_reader_gone_from_standard_output_loses_no_file() {
    // `ugo solve … | head -1`: the pipe is closed before the summary is printed.
    let dir = scratch("closed-pipe");
    let out = dir.join("furnace.h5");
    let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_ugo"))
        .args(["solve", "cases/furnace-box.toml", "-o", out.to_str().unwrap()])
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    drop(child.stdout.take());
    let o = child.wait_with_output().unwrap();
    assert!(o.status.success() && !stderr(&o).contains("panicked"), "{}", stderr(&o));
    assert!(out.exists() && !stderr(&o).contains("Broken pipe"));
}
