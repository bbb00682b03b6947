//! 5.3, area light sources: a 1 × 1 m Lambertian ceiling source of 1000 cd/m² in a black
//! 4 × 4 × 3 m room (Table 12); the points read the emitter through the exact contour
//! integral.

use super::{Solved, compare, solved, solved_hierarchically};

/// CIE 171:2006 Table 12, lx: wall A–F, floor G–N.
const TABLE_12: [(&str, f64); 14] = [
    ("A", 32.68),
    ("B", 75.09),
    ("C", 81.38),
    ("D", 69.12),
    ("E", 53.41),
    ("F", 39.90),
    ("G", 61.27),
    ("H", 79.18),
    ("I", 95.52),
    ("J", 105.89),
    ("K", 105.89),
    ("L", 95.52),
    ("M", 79.18),
    ("N", 61.27),
];

#[test]
fn cie_5_3_area_source_in_a_room() {
    check_5_3(&solved("5.3-area-source"));
}

/// Issue 14.4: the same through the hierarchy.
#[test]
fn cie_5_3_area_source_in_a_room_through_the_hierarchy() {
    check_5_3(&solved_hierarchically("5.3-area-source"));
}

fn check_5_3(s: &Solved) {
    let rows: Vec<(&str, f64, f64)> =
        TABLE_12.iter().map(|&(point, reference)| (point, reference, s.probe(point).illuminance)).collect();
    compare("5.3", &rows);
}
