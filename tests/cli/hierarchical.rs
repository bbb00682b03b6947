//! `--kernel hierarchical` and `[discretization] kernel = "hierarchical"` end to end: the
//! solve, its summary of passes, `/hierarchy` in the HDF5 file and `render` of the leaves;
//! the hierarchy's flags refused with the uniform kernel and checked as its keys are; a
//! case without `kernel` solved by the kernel its size chooses.

use super::{assert_clean_failure, stderr};
use crate::support::{scratch, ugo};

#[test]
fn a_hierarchical_solve_writes_its_passes_and_renders() {
    let dir = scratch("hierarchical");
    let out = dir.join("furnace.h5");
    let args = ["solve", "cases/furnace-box.toml", "--kernel", "hierarchical", "--root-size", "0.5"];
    let o = ugo(&[&args[..], &["--patch-size", "0.1", "-o", out.to_str().unwrap()]].concat());
    assert!(o.status.success(), "{}", stderr(&o));
    let summary = String::from_utf8_lossy(&o.stdout);
    assert!(summary.contains("hierarchical") && summary.contains("pass 0"), "{summary}");

    let file = hdf5::File::open(&out).unwrap();
    let luminance = file.dataset("field/luminance").unwrap().read_dyn::<f64>().unwrap();
    let level = file.dataset("hierarchy/leaf_level").unwrap().read_1d::<u8>().unwrap();
    assert_eq!(luminance.shape()[0], level.len());
    assert!(level.iter().any(|&l| l > 0), "nothing was split");
    assert!(luminance.iter().all(|l| (l / 5.0 - 1.0).abs() < 1e-3), "the white furnace on the leaves");
    let links = file.dataset("hierarchy/passes/links").unwrap().read_1d::<f64>().unwrap();
    assert!(!links.is_empty() && links.iter().all(|&n| n > 0.0));
    let row_error = file.dataset("hierarchy/passes/balance_row_error").unwrap().read_1d::<f64>().unwrap();
    assert_eq!(row_error.len(), links.len());
    assert!(row_error.iter().any(|e| e.is_finite() && *e < 1e-3), "the passes were balanced: {row_error:?}");
    // every pass's operator was built (and timed), the last one's too
    let operator = file.dataset("hierarchy/passes/operator_seconds").unwrap().read_1d::<f64>().unwrap();
    assert_eq!(operator.len(), links.len());
    assert!(operator.iter().all(|&s| s > 0.0), "{operator:?}");
    assert!(summary.contains("operator "), "{summary}");

    let o = ugo(&["render", out.to_str().unwrap(), "-o", dir.to_str().unwrap(), "--shading", "smooth"]);
    assert!(o.status.success(), "{}", stderr(&o));
}

/// Issue 14.8: the furnace cube asked for `--kernel auto`; at 0.025 m its uniform kernel
/// would have 15 · 40⁴ = 3.8e7 facing pairs, so the hierarchy solves it, told on stderr, and
/// the uniform mesh stays one option away.
#[test]
fn a_case_without_kernel_is_solved_by_the_kernel_its_size_chooses() {
    let dir = scratch("automatic");
    let out = dir.join("furnace.h5");
    let o = ugo(&[
        "solve",
        "cases/furnace-box.toml",
        "--patch-size",
        "0.025",
        "--kernel",
        "auto",
        "-o",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let note = stderr(&o);
    assert!(note.contains("ugo: note: no `kernel`") && note.contains("3.840e7 facing pairs"), "{note}");
    let file = hdf5::File::open(&out).unwrap();
    let luminance = file.dataset("field/luminance").unwrap().read_dyn::<f64>().unwrap();
    assert!(file.dataset("hierarchy/leaf_level").is_ok(), "not the hierarchy");
    let text = |name: &str| file.attr(name).unwrap().read_scalar::<hdf5::types::VarLenUnicode>().unwrap();
    assert_eq!(text("kernel").as_str(), "hierarchical");
    assert!(text("kernel_chosen_by_size").contains("3.840e7 facing pairs"));
    assert!(luminance.iter().all(|l| (l / 5.0 - 1.0).abs() < 1e-3), "the white furnace on the leaves");

    // `--kernel uniform`: the uniform mesh at the size asked for, no note
    let o = ugo(&["info", "cases/furnace-box.toml", "--patch-size", "0.025", "--kernel", "uniform"]);
    let err = stderr(&o);
    assert!(o.status.success() && !err.contains("note:"), "{err}");
    let summary = String::from_utf8_lossy(&o.stdout);
    assert!(summary.contains("patch size                0.025 m") && summary.contains("9600"), "{summary}");
}

#[test]
fn the_hierarchys_flags_are_refused_with_the_uniform_kernel_and_checked_as_its_keys() {
    let o = ugo(&["solve", "cases/furnace-box.toml", "--root-size", "1"]);
    let err = assert_clean_failure(&o);
    assert!(err.contains("--root-size applies only to the hierarchical kernel"), "{err}");
    assert!(err.contains("--kernel hierarchical"), "{err}");
    let hierarchical = ["solve", "cases/furnace-box.toml", "--kernel", "hierarchical"];
    let err = assert_clean_failure(&ugo(&[&hierarchical[..], &["--link-tolerance", "-1"]].concat()));
    assert!(err.contains("--link-tolerance must be a number greater than 0, got -1"), "{err}");
    // the rule of `root_size` in a case file, for the flag: roots no smaller than the leaves
    let err = assert_clean_failure(&ugo(&[&hierarchical[..], &["--root-size", "0.05"]].concat()));
    assert!(err.contains("--root-size (0.05 m) must not be smaller than patch_size (0.1 m)"), "{err}");
    let err = assert_clean_failure(&ugo(&["solve", "cases/furnace-box.toml", "--kernel", "cases/x.h5"]));
    assert!(err.contains("--kernel-file"), "{err}");
    // `--kernel uniform` on a hierarchical case sets its `root_size` and `link_tolerance` aside
    let o = ugo(&["info", "cases/office.toml", "--kernel", "uniform", "--patch-size", "1"]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(String::from_utf8_lossy(&o.stdout).contains("uniform kernel"));
}

/// The spelling before issue 33 still reads, told on stderr, to the same discretization.
#[test]
fn the_old_spelling_is_read_with_a_note() {
    let dir = scratch("old-spelling");
    let case = dir.join("office.toml");
    let text = std::fs::read_to_string("cases/office.toml").unwrap().replace(
        "patch_size = 0.15\nkernel = \"hierarchical\"\nroot_size = 1\nlink_tolerance = 0.01",
        "patch_size = 1\nmethod = \"hierarchical\"\ntolerance = 0.01\nsmallest = 0.15",
    );
    assert!(text.contains("smallest = 0.15"), "the office's [discretization] changed");
    std::fs::write(&case, text).unwrap();
    std::fs::copy("cases/office-downlight.ies", dir.join("office-downlight.ies")).unwrap();
    let (old, new) = (ugo(&["info", case.to_str().unwrap()]), ugo(&["info", "cases/office.toml"]));
    assert!(old.status.success(), "{}", stderr(&old));
    let err = stderr(&old);
    assert!(err.contains("ugo: note:") && err.contains("`smallest = 0.15` is the old spelling"), "{err}");
    let figures = |o: &std::process::Output| {
        let out = String::from_utf8_lossy(&o.stdout).into_owned();
        out.lines().filter(|l| !l.starts_with("ugo info:")).collect::<Vec<_>>().join("\n")
    };
    assert_eq!(figures(&old), figures(&new));
}

/// Issue 14.6: `ugo bench --kernel hierarchical` reports leaves, links and time over leaf
/// sizes with the fitted exponents, and refuses `--export` (no matrix).
#[test]
fn bench_reports_the_hierarchys_links_against_the_leaves() {
    let dir = scratch("bench-hierarchical");
    let json = dir.join("bench.json");
    let args = ["bench", "--kernel", "hierarchical", "--root-size", "0.25", "--link-tolerance", "3e-2"];
    let sizes = ["--patch-size", "0.1", "--rays", "20000", "--scaling", "0.25,0.15", "--json", json.to_str().unwrap()];
    let o = ugo(&[&args[..], &sizes[..]].concat());
    assert!(o.status.success(), "{}", stderr(&o));
    let report: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    for key in [
        "occlusion_rays_per_second",
        "occlusion_rays_per_second_one_thread",
        "factored_apply_seconds",
        "links_exponent",
        "time_exponent",
    ] {
        assert!(report[key].as_f64().is_some_and(f64::is_finite), "{key}: {}", report[key]);
    }
    let levels = report["hierarchy"].as_array().unwrap();
    assert_eq!(levels.len(), 3, "two sizes and the case's own");
    for l in levels {
        let (n, links) = (l["leaves"].as_f64().unwrap(), l["links"].as_f64().unwrap());
        assert!(links > 0.0 && links < n * n, "{l}");
        for key in ["rays", "nodes", "seconds", "linking_seconds", "operator_seconds", "links_per_n2", "operator_bytes"]
        {
            assert!(l[key].as_f64().is_some_and(|v| v > 0.0), "{key}: {l}");
        }
        let stages = l["linking_seconds"].as_f64().unwrap() + l["operator_seconds"].as_f64().unwrap();
        assert!(stages <= l["refinement_seconds"].as_f64().unwrap(), "the stages are of the build: {l}");
    }
    assert!(levels[0]["leaves"].as_u64() < levels[2]["leaves"].as_u64(), "sorted by N");
    let err = assert_clean_failure(&ugo(&[&args[..], &["--export", "/tmp/never"]].concat()));
    assert!(err.contains("stores none"), "{err}");
}
