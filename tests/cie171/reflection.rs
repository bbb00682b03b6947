//! 5.6, light reflection over diffuse surfaces (scenario 2): a 4 × 4 m floor of ρ = 0.3
//! under E_hz = 10 000 lx; `E/(E_hz ρ)` in % is the configuration factor (Table 17).

use super::{Solved, compare, solved, solved_hierarchically};
use ugo::readout::illuminance::patch_illuminance;

/// CIE 171:2006 Table 17 (scenario 2), E/(E_hz ρ) in %: vertical plane B–F, horizontal G–N.
const TABLE_17: [(&str, f64); 13] = [
    ("B", 35.901),
    ("C", 27.992),
    ("D", 21.639),
    ("E", 16.716),
    ("F", 12.967),
    ("G", 26.80),
    ("H", 30.94),
    ("I", 33.98),
    ("J", 35.57),
    ("K", 35.57),
    ("L", 33.98),
    ("M", 30.94),
    ("N", 26.80),
];

#[test]
fn cie_5_6_configuration_factors_of_a_lit_floor() {
    check_5_6(&solved("5.6-diffuse-reflection"));
}

/// Issue 14.4: the same through the hierarchy.
#[test]
fn cie_5_6_configuration_factors_of_a_lit_floor_through_the_hierarchy() {
    check_5_6(&solved_hierarchically("5.6-diffuse-reflection"));
}

fn check_5_6(s: &Solved) {
    let (e_hz, rho) = (10_000.0, 0.3);
    let lit = patch_illuminance(&s.model.direct.arriving, 1);
    assert!(
        lit.iter().all(|e| (e / e_hz - 1.0).abs() < 1e-12),
        "parallel light from the zenith lights the floor evenly"
    );
    let rows: Vec<(&str, f64, f64)> = TABLE_17
        .iter()
        .map(|&(point, reference)| {
            let p = s.probe(point);
            assert_eq!(p.direct, 0.0, "{point} faces away from the light");
            (point, reference, 100.0 * p.illuminance / (e_hz * rho))
        })
        .collect();
    compare("5.6", &rows);
}
