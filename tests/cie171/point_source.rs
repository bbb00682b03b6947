//! 5.2, point light sources: a Lambertian 1000 cd source 3 m above a plane,
//! `E = I0 h² / d⁴` (Table 11).

use super::{Solved, compare, solved, solved_hierarchically};
use ugo::luminaire::Light;
use ugo::photometry::Distribution;
use ugo::progress::Silent;
use ugo::readout::probe::read_probes;

/// CIE 171:2006 Table 11, lx.
const TABLE_11: [(&str, f64); 10] = [
    ("A", 111.11),
    ("B", 105.21),
    ("C", 90.02),
    ("D", 71.11),
    ("E", 99.73),
    ("F", 85.64),
    ("G", 68.06),
    ("H", 74.36),
    ("I", 59.98),
    ("J", 49.39),
];

#[test]
fn cie_5_2_point_source_over_a_plane() {
    check_5_2(&solved("5.2-point-source"));
}

/// Issue 14.4: the same through the hierarchy.
#[test]
fn cie_5_2_point_source_over_a_plane_through_the_hierarchy() {
    check_5_2(&solved_hierarchically("5.2-point-source"));
}

fn check_5_2(s: &Solved) {
    let rows: Vec<(&str, f64, f64)> =
        TABLE_11.iter().map(|&(point, reference)| (point, reference, s.probe(point).illuminance)).collect();
    compare("5.2", &rows);
    for p in &s.probes {
        assert_eq!(p.direct, p.illuminance, "a black plane reflects nothing: {p:?}");
    }
}

#[test]
fn an_analytic_lambertian_source_gives_the_closed_form_exactly() {
    let mut s = solved("5.2-point-source");
    let Light::Point { distribution, .. } = &mut s.model.sources[0].light else { panic!("a point source") };
    *distribution = Distribution::Lambertian { peak: 1000.0 };
    let exact = |x: f64, z: f64| 1000.0 * 9.0 / (9.0 + x * x + z * z).powi(2);
    let field = ugo::readout::field::Field::from_unknowns(&s.x, 1);
    for (probe, reading) in s.scene.probes.iter().zip(read_probes(&s.scene.probes, &s.model, &field, &Silent)) {
        let e = exact(probe.position.x, probe.position.z);
        assert!((reading.illuminance / e - 1.0).abs() < 1e-12, "{}: {} vs {e}", probe.name, reading.illuminance);
        let file = s.probe(&probe.name).illuminance;
        assert!((file / e - 1.0).abs() < 2e-3, "the 5° IES table interpolates cos within 0.2 %: {file} vs {e}");
    }
}
