//! The sun's position from a site and a time (Spencer's series): the declination at the
//! solstices, and the sun's highest point of the day at `90° − φ + δ` due south.

use ugo::sky::{SiteTime, day_of_year, declination_and_equation_of_time};

#[test]
fn the_declination_at_the_solstices_is_the_tilt_of_the_earth() {
    let g = |day: u32| std::f64::consts::TAU * (day as f64 - 1.0) / 365.0;
    let june = declination_and_equation_of_time(g(day_of_year(2026, 6, 21).unwrap())).0.to_degrees();
    let december = declination_and_equation_of_time(g(day_of_year(2026, 12, 21).unwrap())).0.to_degrees();
    assert!((june - 23.44).abs() < 0.1, "{june}");
    assert!((december + 23.44).abs() < 0.1, "{december}");
}

#[test]
fn days_of_the_year_count_leap_years() {
    assert_eq!(day_of_year(2024, 3, 1), Some(61));
    assert_eq!(day_of_year(2026, 3, 1), Some(60));
    assert_eq!(day_of_year(2026, 12, 31), Some(365));
    assert_eq!(day_of_year(2026, 2, 29), None);
    assert_eq!(day_of_year(2026, 13, 1), None);
}

#[test]
fn the_sun_culminates_due_south_at_ninety_minus_latitude_plus_declination() {
    // Berlin, 21 June, local standard time UTC+1: the highest altitude of the day.
    let at = |hours: f64| {
        SiteTime { latitude_deg: 52.5, longitude_deg: 13.4, day_of_year: 172, hours, timezone_h: 1.0 }.sun()
    };
    let (mut best, mut when) = (f64::MIN, 0.0);
    for minute in 0..24 * 60 {
        let s = at(minute as f64 / 60.0);
        if s.altitude_deg > best {
            (best, when) = (s.altitude_deg, minute as f64 / 60.0);
        }
    }
    assert!((best - (90.0 - 52.5 + 23.44)).abs() < 0.15, "{best}");
    assert!((at(when).azimuth_deg - 180.0).abs() < 1.0, "{}", at(when).azimuth_deg);
    // Solar noon: 12:00 + 4 min/° × (15° − 13.4°) + the equation of time (about −1.7 min).
    assert!((when - (12.0 + (4.0 * 1.6 + 1.7) / 60.0)).abs() < 3.0 / 60.0, "{when}");
    assert!(at(5.0).azimuth_deg < 90.0 && at(20.0).azimuth_deg > 270.0, "rises north-east, sets north-west");
}
