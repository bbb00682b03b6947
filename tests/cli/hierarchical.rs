//! `--assembly hierarchical` and `[discretization] method = "hierarchical"` end to end: the
//! solve, its summary of passes, `/hierarchy` in the HDF5 file and `render` of the leaves;
//! the hierarchy's keys refused with the explicit kernel; a case without `method` solved by
//! the kernel its size chooses.

use super::{assert_clean_failure, stderr};
use crate::support::{scratch, ugo};

#[test]
fn a_hierarchical_solve_writes_its_passes_and_renders() {
    let dir = scratch("hierarchical");
    let out = dir.join("furnace.h5");
    let args = ["solve", "cases/furnace-box.toml", "--assembly", "hierarchical", "--patch-size", "0.5"];
    let o = ugo(&[&args[..], &["--smallest", "0.1", "-o", out.to_str().unwrap()]].concat());
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

    let o = ugo(&["render", out.to_str().unwrap(), "-o", dir.to_str().unwrap(), "--shading", "smooth"]);
    assert!(o.status.success(), "{}", stderr(&o));
}

/// Issue 14.8: the furnace cube has no `method`; at 0.025 m its explicit kernel would have
/// 15 · 40⁴ = 3.8e7 facing pairs, so the hierarchy solves it, told on stderr, and the
/// uniform mesh stays one option away.
#[test]
fn a_case_without_method_is_solved_by_the_kernel_its_size_chooses() {
    let dir = scratch("automatic");
    let out = dir.join("furnace.h5");
    let o = ugo(&["solve", "cases/furnace-box.toml", "--patch-size", "0.025", "-o", out.to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    let note = stderr(&o);
    assert!(note.contains("ugo: note: no `method`") && note.contains("3.840e7 facing pairs"), "{note}");
    let file = hdf5::File::open(&out).unwrap();
    let luminance = file.dataset("field/luminance").unwrap().read_dyn::<f64>().unwrap();
    assert!(file.dataset("hierarchy/leaf_level").is_ok(), "not the hierarchy");
    let text = |name: &str| file.attr(name).unwrap().read_scalar::<hdf5::types::VarLenUnicode>().unwrap();
    assert_eq!(text("assembly").as_str(), "hierarchical");
    assert!(text("assembly_chosen_by_size").contains("3.840e7 facing pairs"));
    assert!(luminance.iter().all(|l| (l / 5.0 - 1.0).abs() < 1e-3), "the white furnace on the leaves");

    // `--assembly explicit`: the uniform mesh at the size asked for, no note
    let o = ugo(&["info", "cases/furnace-box.toml", "--patch-size", "0.025", "--assembly", "explicit"]);
    let err = stderr(&o);
    assert!(o.status.success() && !err.contains("note:"), "{err}");
    let summary = String::from_utf8_lossy(&o.stdout);
    assert!(summary.contains("patch size                0.025 m") && summary.contains("9600"), "{summary}");
}

#[test]
fn the_hierarchys_keys_are_refused_with_the_explicit_kernel() {
    let o = ugo(&["solve", "cases/furnace-box.toml", "--smallest", "0.1"]);
    let err = assert_clean_failure(&o);
    assert!(err.contains("--assembly hierarchical"), "{err}");
    let o = ugo(&["solve", "cases/furnace-box.toml", "--assembly", "hierarchical", "--link-tolerance", "-1"]);
    assert_clean_failure(&o);
}

/// Issue 14.6: `ugo bench --assembly hierarchical` reports leaves, links and time over
/// smallest element sizes with the fitted exponents, and refuses `--export` (no matrix).
#[test]
fn bench_reports_the_hierarchys_links_against_the_leaves() {
    let dir = scratch("bench-hierarchical");
    let json = dir.join("bench.json");
    let args = ["bench", "--assembly", "hierarchical", "--patch-size", "0.25", "--link-tolerance", "3e-2"];
    let sizes = ["--smallest", "0.1", "--rays", "20000", "--scaling", "0.25,0.15", "--json", json.to_str().unwrap()];
    let o = ugo(&[&args[..], &sizes[..]].concat());
    assert!(o.status.success(), "{}", stderr(&o));
    let report: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    for key in ["occlusion_rays_per_second", "factored_apply_seconds", "links_exponent", "time_exponent"] {
        assert!(report[key].as_f64().is_some_and(f64::is_finite), "{key}: {}", report[key]);
    }
    let levels = report["hierarchy"].as_array().unwrap();
    assert_eq!(levels.len(), 3, "two sizes and the case's own");
    for l in levels {
        let (n, links) = (l["leaves"].as_f64().unwrap(), l["links"].as_f64().unwrap());
        assert!(links > 0.0 && links < n * n, "{l}");
        for key in ["rays", "nodes", "seconds", "links_per_n2", "operator_bytes"] {
            assert!(l[key].as_f64().is_some_and(|v| v > 0.0), "{key}: {l}");
        }
    }
    assert!(levels[0]["leaves"].as_u64() < levels[2]["leaves"].as_u64(), "sorted by N");
    let err = assert_clean_failure(&ugo(&[&args[..], &["--export", "/tmp/never"]].concat()));
    assert!(err.contains("stores none"), "{err}");
}
