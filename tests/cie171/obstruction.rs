//! 5.7, diffuse reflections with internal obstructions: a sunlit wall (ρ = 0.6) seen past
//! a black obstruction. `E/(E_v ρ)` in %, the corrected values (the printed Table 19 was
//! computed with the wrong geometry; docs/references.md).

use super::{Solved, compare, solved, solved_hierarchically};
use ugo::readout::illuminance::patch_illuminance;

/// Corrected CIE 171:2006 Table 19, E/(E_v ρ) in %: wall A–F, floor G–K.
const CORRECTED_19: [(&str, f64); 11] = [
    ("A", 16.07),
    ("B", 16.33),
    ("C", 15.40),
    ("D", 13.32),
    ("E", 10.32),
    ("F", 7.08),
    ("G", 3.38),
    ("H", 3.63),
    ("I", 3.01),
    ("J", 0.0),
    ("K", 0.0),
];

#[test]
fn cie_5_7_reflection_past_an_obstruction() {
    check_5_7(&solved("5.7-obstruction"));
}

/// Issue 14.4: the same through the hierarchy.
#[test]
fn cie_5_7_reflection_past_an_obstruction_through_the_hierarchy() {
    check_5_7(&solved_hierarchically("5.7-obstruction"));
}

fn check_5_7(s: &Solved) {
    let (e_v, rho) = (10_000.0, 0.6);
    let wall = s.scene.surface_index("S2").unwrap() as u32;
    let lit = patch_illuminance(&s.model.direct.arriving, 1);
    for (p, e) in s.model.mesh.patches.iter().zip(&lit) {
        if p.surface == wall {
            assert!((e / e_v - 1.0).abs() < 1e-9, "the sun lights S2 evenly with E_v: {e}");
        }
    }
    let rows: Vec<(&str, f64, f64)> = CORRECTED_19
        .iter()
        .map(|&(point, reference)| {
            let p = s.probe(point);
            (point, reference, 100.0 * (p.illuminance - p.direct) / (e_v * rho))
        })
        .collect();
    compare("5.7", &rows);
    let sunlit = s.probe("K");
    let exact = 20_000.0 * 60f64.to_radians().sin();
    assert!((sunlit.direct / exact - 1.0).abs() < 1e-12, "K stands in the sun: {}", sunlit.direct);
    assert_eq!(s.probe("G").direct, 0.0, "G lies in the shadow of S1-v");
}
