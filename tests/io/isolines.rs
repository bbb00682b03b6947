//! Isolux lines by marching squares (issue 17, item 1), against fields whose level lines
//! are known.

use ugo::io::isolines;

#[test]
fn a_linear_field_has_straight_level_lines_where_it_equals_the_level() {
    // value = a + 0.5 b on a 5 × 4 lattice: the line a + 0.5 b = 2.5.
    let values: Vec<f64> = (0..4).flat_map(|b| (0..5).map(move |a| a as f64 + 0.5 * b as f64)).collect();
    let segments = isolines(&values, [5, 4], 2.5);
    assert_eq!(segments.len(), 5, "{segments:?}");
    for [p, q] in &segments {
        for (a, b) in [p, q] {
            assert!((a + 0.5 * b - 2.5).abs() < 1e-12, "({a}, {b}) is off the line");
        }
    }
    let length: f64 = segments.iter().map(|[p, q]| ((p.0 - q.0).powi(2) + (p.1 - q.1).powi(2)).sqrt()).sum();
    // From (2.5, 0) to (1.0, 3): the whole line across the lattice.
    assert!((length - (1.5f64.powi(2) + 9.0).sqrt()).abs() < 1e-12, "length {length}");
    assert!(isolines(&values, [5, 4], 100.0).is_empty());
}

#[test]
fn a_saddle_is_split_by_its_centre_value() {
    // Corners (0,0) = 1, (1,0) = 0, (1,1) = 1, (0,1) = 0: the centre 0.5 sides with the ones,
    // so the lines cut off the zero corners (1,0) and (0,1).
    let segments = isolines(&[1.0, 0.0, 0.0, 1.0], [2, 2], 0.5);
    assert_eq!(segments.len(), 2);
    for [p, q] in segments {
        let mid = ((p.0 + q.0) / 2.0, (p.1 + q.1) / 2.0);
        assert!(mid == (0.75, 0.25) || mid == (0.25, 0.75), "{mid:?}");
    }
}
