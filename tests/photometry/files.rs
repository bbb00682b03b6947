//! Every synthetic file parses, integrates to its stated flux (or, for absolute
//! photometry, to its closed form) within 0.5 %, and reproduces its symmetry pointwise.

use super::read;
use std::f64::consts::PI;

const I0: f64 = 1000.0;

/// (file, closed-form flux of the distribution written into it, lm, whether the file states it).
const FILES: [(&str, f64, bool); 16] = [
    ("c-axial-lambert-2002.ies", PI * I0, true),
    ("c-quadrant-1995.ies", PI * I0, true),
    ("c-bilateral-0-180-2002.ies", PI * I0, true),
    ("c-bilateral-90-270-1995.ies", PI * I0, true),
    ("c-full-2019.ies", PI * I0, true),
    ("c-uplight-absolute-2002.ies", PI * I0, false),
    ("c-isotropic-tilt-2002.ies", 4.0 * PI * I0, true),
    ("b-lateral-2002.ies", PI * I0, true),
    ("b-front-2002.ies", PI * I0, true),
    ("a-front-2002.ies", PI * I0, true),
    ("b-sphere-isotropic-1995.ies", 4.0 * PI * I0, true),
    ("isym0-none.ldt", 1000.0, true),
    ("isym1-axial-isotropic.ldt", 1000.0, true),
    ("isym2-c0-c180.ldt", 1000.0, true),
    ("isym3-c90-c270.ldt", 1000.0, true),
    ("isym4-quadrant.ldt", 1000.0, true),
];

#[test]
fn every_synthetic_file_integrates_to_its_flux_within_half_a_percent() {
    for (name, exact, stated) in FILES {
        let table = read(name);
        let flux = table.flux();
        let error = flux / exact - 1.0;
        eprintln!("{name:<30} {:<70} flux {flux:>10.3} lm, closed form {exact:>10.3}, {error:+.2e}", table.description);
        assert!(error.abs() < 5e-3, "{name}: flux {flux} against {exact}");
        match (stated, table.stated_flux) {
            (true, Some(s)) => assert!((flux / s - 1.0).abs() < 5e-3, "{name}: flux {flux}, the file states {s}"),
            (false, None) => {}
            (_, s) => panic!("{name}: stated flux {s:?}"),
        }
    }
}

/// `I0 cosγ` times an azimuthal factor, at a tabulated γ.
fn lambert(gamma: f64, factor: f64) -> f64 {
    I0 * gamma.to_radians().cos() * factor
}

#[test]
fn symmetric_files_are_expanded_by_the_right_mirror_planes() {
    let cos = |d: f64| d.to_radians().cos();
    let sin = |d: f64| d.to_radians().sin();
    // (file, azimuth outside the stored range, the factor the generator used there)
    let cases: [(&str, f64, f64); 6] = [
        ("c-quadrant-1995.ies", 120.0, 1.0 + 0.5 * cos(240.0)),
        ("c-quadrant-1995.ies", 300.0, 1.0 + 0.5 * cos(600.0)),
        ("c-bilateral-0-180-2002.ies", 210.0, 1.0 + 0.5 * cos(210.0)),
        ("c-bilateral-90-270-1995.ies", 30.0, 1.0 + 0.5 * sin(30.0)),
        ("c-bilateral-90-270-1995.ies", 315.0, 1.0 + 0.5 * sin(315.0)),
        ("c-full-2019.ies", 255.0, 1.0 + 0.3 * cos(255.0) + 0.2 * sin(255.0)),
    ];
    for (name, c, factor) in cases {
        let got = read(name).at(c, 30.0);
        assert!((got / lambert(30.0, factor) - 1.0).abs() < 1e-4, "{name} at C{c}: {got}");
    }
    let per_klm = |table: &ugo::photometry::IntensityDistribution, c: f64| table.at(c, 30.0);
    let ldt = [
        ("isym2-c0-c180.ldt", 285.0, 1.0 + 0.5 * cos(285.0)),
        ("isym3-c90-c270.ldt", 15.0, 1.0 + 0.5 * sin(15.0)),
        ("isym3-c90-c270.ldt", 345.0, 1.0 + 0.5 * sin(345.0)),
        ("isym4-quadrant.ldt", 225.0, 1.0 + 0.5 * cos(450.0)),
        ("isym0-none.ldt", 135.0, 1.0 + 0.3 * cos(135.0) + 0.2 * sin(135.0)),
    ];
    for (name, c, factor) in ldt {
        let got = per_klm(&read(name), c);
        let exact = 1000.0 / PI * cos(30.0) * factor;
        assert!((got / exact - 1.0).abs() < 1e-4, "{name} at C{c}: {got} against {exact}");
    }
}

#[test]
fn an_axially_symmetric_file_is_the_same_at_every_azimuth() {
    let table = read("c-axial-lambert-2002.ies");
    for c in [0.0, 47.0, 180.0, 359.9] {
        assert!((table.at(c, 45.0) / lambert(45.0, 1.0) - 1.0).abs() < 1e-4);
    }
    assert_eq!(table.at(10.0, 95.0), 0.0, "nothing above the last vertical angle");
}

#[test]
fn the_2019_file_generation_field_does_not_scale_the_candela() {
    let table = read("c-full-2019.ies");
    assert!((table.at(0.0, 0.0) / (I0 * 1.3) - 1.0).abs() < 1e-6, "{}", table.at(0.0, 0.0));
}

#[test]
fn tilt_data_is_read_and_interpolated() {
    let tilt = read("c-isotropic-tilt-2002.ies").tilt.expect("TILT=INCLUDE");
    assert_eq!(
        (tilt.geometry, tilt.angles.clone(), tilt.factors.clone()),
        (1, vec![0.0, 45.0, 90.0], vec![1.0, 0.8, 0.5])
    );
    assert!((tilt.factor(22.5) - 0.9).abs() < 1e-12);
    assert_eq!((tilt.factor(-5.0), tilt.factor(120.0)), (1.0, 0.5));
    assert!(read("c-axial-lambert-2002.ies").tilt.is_none());
}
