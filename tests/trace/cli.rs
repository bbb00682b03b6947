//! `ugo trace`, `ugo agree` and `ugo compare --photons` end to end on the furnace box,
//! and their failures as clear messages.

use crate::support::{scratch, ugo};
use std::process::Output;
use ugo::io::{read_exr, read_solution};

fn text(o: &Output) -> String {
    format!("{}{}", String::from_utf8_lossy(&o.stdout), String::from_utf8_lossy(&o.stderr))
}

fn ok(args: &[&str]) -> String {
    let o = ugo(args);
    assert!(o.status.success(), "ugo {args:?}: {}", text(&o));
    String::from_utf8_lossy(&o.stdout).into_owned()
}

fn fails(args: &[&str]) -> String {
    let o = ugo(args);
    let err = String::from_utf8_lossy(&o.stderr).into_owned();
    assert!(!o.status.success(), "ugo {args:?} should fail");
    assert!(err.starts_with("ugo: error:") && !err.contains("panicked"), "{err}");
    err
}

#[test]
fn trace_writes_images_and_fields_that_agree_reads() {
    let dir = scratch("trace");
    let d = dir.to_str().unwrap();
    let printed = ok(&["trace", "cases/furnace-box.toml", "--camera", "inside", "--spp", "16", "-o", d]);
    assert!(printed.contains("paths/s") && printed.contains("rays/s"), "{printed}");
    let mean = read_exr(&dir.join("furnace-box-inside-trace.exr")).unwrap();
    let error = read_exr(&dir.join("furnace-box-inside-trace-stderr.exr")).unwrap();
    assert_eq!((mean.width, mean.height), (32, 32));
    let n = mean.luminance.len() as f64;
    let m = mean.luminance.iter().sum::<f64>() / n;
    let s = error.luminance.iter().map(|e| e * e).sum::<f64>().sqrt() / n;
    assert!(s > 0.0 && ((m - 5.0) / s).abs() < 3.0, "image mean {m} ± {s}, exact 5");

    let forward = dir.join("forward.h5");
    let f = forward.to_str().unwrap();
    let printed =
        ok(&["trace", "cases/furnace-box.toml", "--forward", "--photons", "200000", "--patch-size", "0.25", "-o", f]);
    assert!(printed.contains("photons/s") && printed.contains("scattered flux"), "{printed}");
    let stored = read_solution(&forward).unwrap();
    assert_eq!(stored.method, "forward");
    assert_eq!(stored.standard_error.as_ref().map(Vec::len), Some(stored.luminance.len()));
    ok(&["render", f, "-o", d]);

    let solved = dir.join("solved.h5");
    let s = solved.to_str().unwrap();
    ok(&["solve", "cases/furnace-box.toml", "--patch-size", "0.25", "--kernel", "uniform", "-o", s]);
    let printed = ok(&["agree", s, f]);
    assert!(printed.contains("rms z") && printed.contains("room"), "{printed}");
    let image = dir.join("furnace-box-inside-trace.exr");
    let printed = ok(&["agree", s, image.to_str().unwrap(), "--samples", "4"]);
    assert!(printed.contains("per pixel: 32 × 32"), "{printed}");

    assert!(fails(&["agree", s, s]).contains("standard errors"));
    let coarse = dir.join("coarse.h5");
    ok(&["solve", "cases/furnace-box.toml", "--patch-size", "0.5", "-o", coarse.to_str().unwrap()]);
    // (at 0.5 m the size rule takes the hierarchy: the way out is to bin on its leaves)
    let told = fails(&["agree", coarse.to_str().unwrap(), f]);
    assert!(told.contains("discretize differently") && told.contains("--bins-of"), "{told}");
}

#[test]
fn compare_includes_a_forward_reference() {
    let dir = scratch("compare-mc");
    let out = dir.join("c.h5");
    let plot = dir.join("c.png");
    let printed = ok(&[
        "compare",
        "cases/furnace-box.toml",
        "--patch-size",
        "0.5",
        "--methods",
        "neumann,direct",
        "--photons",
        "50000",
        "-o",
        out.to_str().unwrap(),
        "--plot",
        plot.to_str().unwrap(),
    ]);
    assert!(printed.contains("forward MC") && printed.contains("rms z"), "{printed}");
}

#[test]
fn trace_refuses_bad_requests() {
    let dir = scratch("trace-bad");
    let d = dir.to_str().unwrap();
    assert!(fails(&["trace", "cases/furnace-box.toml", "--camera", "nowhere", "-o", d]).contains("unknown camera"));
    assert!(fails(&["trace", "cases/furnace-box.toml", "--forward", "--photons", "1"]).contains("--photons"));
    assert!(fails(&["trace", "cases/furnace-box.toml", "--spp", "0", "-o", d]).contains("--spp"));
    let dark = dir.join("dark.toml");
    let case = std::fs::read_to_string("cases/furnace-box.toml").unwrap().replace("emission = { luminance = 1.0 }", "");
    std::fs::write(&dark, case).unwrap();
    assert!(fails(&["trace", dark.to_str().unwrap(), "-o", d]).contains("emits"));
}

/// Light tracing starts photons from the sky through the openings (once refused).
#[test]
fn a_forward_trace_of_a_daylit_case_starts_photons_at_its_window() {
    let dir = scratch("trace-daylit");
    let out = dir.join("daylit.h5");
    let args = ["trace", "cases/daylit-office.toml", "--forward", "--photons", "20000", "--patch-size", "1"];
    let printed = ok(&[&args[..], &["-o", out.to_str().unwrap()]].concat());
    assert!(printed.contains("scattered flux") && out.exists(), "{printed}");
}

#[test]
fn a_forward_trace_bins_on_a_hierarchical_solutions_leaves_and_agree_reads_them_leaf_by_leaf() {
    let dir = scratch("bins-of");
    let (solved, forward) = (dir.join("solved.h5"), dir.join("forward.h5"));
    let (s, f) = (solved.to_str().unwrap(), forward.to_str().unwrap());
    let hierarchical = ["--kernel", "hierarchical", "--root-size", "0.5", "--patch-size", "0.25"];
    ok(&[&["solve", "cases/furnace-box.toml", "-o", s][..], &hierarchical].concat());
    let leaves = read_solution(&solved).unwrap().mesh.len();
    let printed = ok(&["trace", "cases/furnace-box.toml", "--forward", "--photons", "400000", "--bins-of", s, "-o", f]);
    assert!(printed.contains(&format!("patches N × cells K  {leaves} × 1")), "{printed}");
    assert_eq!(read_solution(&forward).unwrap().mesh.len(), leaves);
    // the white furnace is 5 cd/m² on every leaf, so what agree reads is the trace's noise
    let printed = ok(&["agree", s, f, "--precise", "0.02"]);
    assert!(printed.contains(&format!("per (patch, cell): {leaves} × 1")), "{printed}");
    assert!(printed.contains("bins precise to 2.0 %") && printed.contains("95th percentile"), "{printed}");
    // every leaf of the furnace emits, so none has a place (placement::places)
    assert!(
        printed.contains("by place")
            && printed.lines().any(|l| l.split_whitespace().eq(["open", "0", "0.000", "%", "0"])),
        "{printed}"
    );

    assert!(fails(&["trace", "cases/furnace-box.toml", "--bins-of", s]).contains("--forward"));
    let other = fails(&["trace", "cases/cornell-box.toml", "--forward", "--bins-of", s]);
    assert!(other.contains("another case"), "{other}");
    assert!(fails(&["agree", s, f, "--precise", "0"]).contains("--precise"));
}
