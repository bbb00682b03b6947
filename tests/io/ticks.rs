//! Round tick values (issue 17, item 1): 1-2-5 steps, never 561.6.

use ugo::io::{log_ticks, round_125, round_top, step, tick_label, ticks};

#[test]
fn linear_ticks_step_by_one_two_or_five_times_a_power_of_ten() {
    assert_eq!(step(0.0, 561.6, 6), 100.0);
    assert_eq!(ticks(0.0, 561.6, 6), [0.0, 100.0, 200.0, 300.0, 400.0, 500.0]);
    assert_eq!(round_top(0.0, 561.6, 6), 600.0);
    assert_eq!(ticks(-2.0, 2.0, 8), [-2.0, -1.5, -1.0, -0.5, 0.0, 0.5, 1.0, 1.5, 2.0]);
    assert_eq!(ticks(0.05, 0.51, 5), [0.1, 0.2, 0.3, 0.4, 0.5]);
    for (lo, hi, most) in [(0.0, 1712.0, 6), (3.3, 4.1, 4), (-0.7, 12.9, 7), (0.0, 1e-3, 5)] {
        let s = step(lo, hi, most);
        let mantissa = s / 10f64.powf(s.log10().floor());
        assert!([1.0, 2.0, 5.0].iter().any(|m| (mantissa - m).abs() < 1e-9), "step {s}");
        let t = ticks(lo, hi, most);
        assert!(t.len() <= most + 1 && t.len() >= 2, "{t:?}");
        assert!(t.iter().all(|&v| v >= lo - 1e-12 && v <= hi + 1e-12 && (v / s - (v / s).round()).abs() < 1e-9));
    }
}

#[test]
fn log_ticks_are_one_two_five_in_every_decade() {
    assert_eq!(log_ticks(3.0, 700.0, 9), [5.0, 10.0, 20.0, 50.0, 100.0, 200.0, 500.0]);
    assert_eq!(log_ticks(0.01, 1000.0, 9), [0.01, 0.1, 1.0, 10.0, 100.0, 1000.0], "powers of ten when crowded");
    assert_eq!((round_125(19.4, false), round_125(194.0, true)), (10.0, 200.0));
    assert_eq!((round_125(50.0, false), round_125(0.7, true)), (50.0, 1.0));
}

#[test]
fn tick_labels_are_short() {
    let labels: Vec<String> = [0.0, 0.5, 0.25, 1500.0, -1.5, 1e-5, 2e7].map(tick_label).to_vec();
    assert_eq!(labels, ["0", "0.5", "0.25", "1500", "-1.5", "1e-5", "2e7"]);
}
