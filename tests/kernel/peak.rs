//! The forecast before meshing holds the mesh's real peak (issue 37, point 7): a model the
//! forecast lets through must not outgrow it in meshing and building its ray caster. The
//! furnace box at `--patch-size 5e-4` (1.5·10⁶ roots of 2 mm) is meshed and its BVH built;
//! the process's peak resident memory when the exposed areas begin is compared with
//! `ugo info`'s "memory before links". Before the forecast counted the tessellated polygons
//! and the BVH's build, it said 629 MiB against a measured 1,267 MiB.

use crate::support::{scratch, ugo};
use std::io::{BufRead, BufReader};
use std::process::{Command, Stdio};

const CASE: &str = "cases/furnace-box.toml";
const PATCH: &str = "5e-4";

/// `ugo info`'s "memory before links", bytes.
fn forecast_bytes() -> f64 {
    let o = ugo(&["info", CASE, "--patch-size", PATCH, "--kernel", "auto"]);
    let text = String::from_utf8_lossy(&o.stdout).into_owned();
    let line = text.lines().find(|l| l.contains("memory before links")).unwrap_or_else(|| panic!("{text}"));
    let mut words = line.split_whitespace().skip(3);
    let (value, unit) = (words.next().unwrap().parse::<f64>().unwrap(), words.next().unwrap());
    value
        * match unit {
            "MiB" => (1u64 << 20) as f64,
            "GiB" => (1u64 << 30) as f64,
            _ => panic!("unit {unit} in {line}"),
        }
}

/// The peak resident bytes of `ugo solve` once its exposed areas begin (the mesh and the
/// ray caster built), then stops it.
fn measured_peak_bytes() -> f64 {
    let dir = scratch("peak");
    let mut child = Command::new(env!("CARGO_BIN_EXE_ugo"))
        .args(["solve", CASE, "--patch-size", PATCH, "--kernel", "auto", "-o", dir.join("res.h5").to_str().unwrap()])
        .env("UGO_PROGRESS_SECONDS", "0")
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let lines = BufReader::new(child.stderr.take().unwrap()).lines();
    let seen: Vec<String> = lines.map(|l| l.unwrap()).take_while(|l| !l.contains("exposed areas")).collect();
    let status = std::fs::read_to_string(format!("/proc/{}/status", child.id())).unwrap();
    child.kill().unwrap();
    child.wait().unwrap();
    let line = status.lines().find(|l| l.starts_with("VmHWM:")).unwrap_or_else(|| panic!("{seen:?}"));
    line.split_whitespace().nth(1).unwrap().parse::<f64>().unwrap() * 1024.0
}

#[test]
fn the_forecast_holds_the_peak_of_meshing_and_the_ray_caster() {
    let (forecast, peak) = (forecast_bytes(), measured_peak_bytes());
    eprintln!("forecast {:.0} MiB, measured peak {:.0} MiB", forecast / 1048576.0, peak / 1048576.0);
    assert!(peak <= 1.1 * forecast, "the mesh outgrew its forecast: {peak:.3e} B against {forecast:.3e} B");
    assert!(peak >= 0.7 * forecast, "the forecast is far above the peak: {peak:.3e} B against {forecast:.3e} B");
}
