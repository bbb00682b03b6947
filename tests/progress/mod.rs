//! Progress that tells the truth (issue 17, item 6): the time left at the stage's average
//! rate, and a line every few seconds on stderr when it is not a terminal.

use crate::support::scratch;

#[test]
fn the_time_left_is_the_average_rate_applied_to_what_remains() {
    use ugo::progress::time_left;
    assert_eq!(time_left(10.0, 250, 1000), Some(30.0));
    assert_eq!(time_left(10.0, 1000, 1000), Some(0.0));
    assert_eq!(time_left(10.0, 0, 1000), None, "nothing done: no rate yet");
    assert_eq!(time_left(10.0, 5, 0), None, "no total: nothing to forecast");
}

#[test]
fn a_progress_line_names_the_stage_its_share_and_the_time_left() {
    use ugo::progress::line;
    assert_eq!(line("assembly", 400, 1000, 12.0), "ugo: progress: assembly 40% (400/1000), 12 s, about 18 s left");
    assert_eq!(line("assembly", 0, 1000, 1.0), "ugo: progress: assembly 0% (0/1000), 1 s");
    assert_eq!(line("refinement", 2, 0, 7.0), "ugo: progress: refinement at 2, 7 s");
}

#[test]
fn without_a_terminal_the_solve_prints_progress_lines() {
    let dir = scratch("progress-lines");
    let out = dir.join("furnace.h5");
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_ugo"))
        .args([
            "solve",
            "cases/furnace-box.toml",
            "--patch-size",
            "0.25",
            "--kernel",
            "uniform",
            "-o",
            out.to_str().unwrap(),
        ])
        .env("UGO_PROGRESS_SECONDS", "0")
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{err}");
    let lines: Vec<&str> = err.lines().filter(|l| l.starts_with("ugo: progress: assembly")).collect();
    assert!(lines.len() > 10, "{err}");
    assert!(lines.iter().any(|l| l.contains("100% (") && l.contains("about 0 s left")), "{err}");
    assert!(err.lines().any(|l| l.starts_with("ugo: progress: gauss-seidel") || l.starts_with("ugo: progress: ")));
}
