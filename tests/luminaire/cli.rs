//! `ugo info` and `ugo solve` with luminaires: every CIE case is valid, the summary lists
//! the luminaires, and `/luminaires` and `/field/direct_illuminance` reach the HDF5 file.

use crate::support::{scratch, ugo};

#[test]
fn every_cie_case_is_valid_and_lists_its_luminaires() {
    let mut cases: Vec<_> = std::fs::read_dir("cases/cie171").unwrap().map(|e| e.unwrap().path()).collect();
    cases.retain(|p| p.extension().is_some_and(|e| e == "toml"));
    assert_eq!(cases.len(), 20, "6 with luminaires, 14 daylit: {cases:?}");
    for case in &cases {
        let o = ugo(&["info", case.to_str().unwrap()]);
        assert!(o.status.success(), "{}: {}", case.display(), String::from_utf8_lossy(&o.stderr));
    }
    let o = ugo(&["info", "cases/cie171/5.2-point-source.toml"]);
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(text.contains("lambertian source") && text.contains("the file states 3141.5927 lm"), "{text}");
}

#[test]
fn a_solve_with_luminaires_writes_them_to_hdf5() {
    let dir = scratch("luminaires");
    let out = dir.join("cie52.h5");
    let o = ugo(&["solve", "cases/cie171/5.2-point-source.toml", "-o", out.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let summary = String::from_utf8_lossy(&o.stdout);
    assert!(
        summary.contains("luminaires") && summary.contains("on surfaces lm") && summary.contains("of it direct lx"),
        "{summary}"
    );

    let file = hdf5::File::open(&out).unwrap();
    let read = |name: &str| file.dataset(name).unwrap().read_raw::<f64>().unwrap();
    let names = file.dataset("luminaires/name").unwrap().read_raw::<hdf5::types::VarLenUnicode>().unwrap();
    assert_eq!(names[0].as_str(), "lambertian source");
    let kind = file.dataset("luminaires/kind").unwrap().read_raw::<hdf5::types::VarLenUnicode>().unwrap();
    assert_eq!(kind[0].as_str(), "file");
    assert_eq!(read("luminaires/position"), vec![0.0, 3.0, 0.0]);
    assert_eq!(read("luminaires/direction"), vec![0.0, -1.0, 0.0]);
    let (flux, file_flux) = (read("luminaires/flux")[0], read("luminaires/file_flux")[0]);
    assert!((flux / (1000.0 * std::f64::consts::PI) - 1.0).abs() < 1e-3 && (file_flux - 3141.5927).abs() < 1e-9);
    assert_eq!(read("luminaires/distribution_flux"), vec![flux]);
    let landed = read("luminaires/on_surfaces")[0];
    let areas = read("mesh/areas");
    let direct = read("field/direct_illuminance");
    let weighted: f64 = areas.iter().zip(&direct).map(|(a, e)| a * e).sum();
    assert!((weighted / landed - 1.0).abs() < 1e-12 && landed < flux);
    assert_eq!(read("field/illuminance"), direct, "a black plane: all of its light is direct");
    let emitted: f64 = file.attr("flux_emitted").unwrap().read_scalar().unwrap();
    assert_eq!(emitted, flux);
    let probe = read("probes/illuminance")[0];
    assert!((probe - 1000.0 / 9.0).abs() < 1e-9, "A, at the nadir: {probe}");
    assert_eq!(read("probes/direct"), read("probes/illuminance"));
}
