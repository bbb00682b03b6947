//! The sun's position: from altitude and azimuth, or from a site's latitude and longitude,
//! the date and the local standard time (`docs/daylight.md`).
//!
//! The declination `δ` and the equation of time come from Spencer's Fourier series
//! (Spencer 1971, as used by NOAA's solar calculator), with the fractional year
//! `Γ = 2π (n − 1 + (h − 12)/24)/365`; the true solar time is the clock time plus the
//! equation of time plus `4 min/°` of longitude east of the time zone's meridian; with the
//! hour angle `ω`, the sun is towards `east = −cos δ sin ω`,
//! `north = sin δ cos φ − cos δ sin φ cos ω`, `up = sin δ sin φ + cos δ cos φ cos ω`.
//! About 0.1° of accuracy: ample for daylight.

use glam::DVec3;

/// Where the sun is seen from the site.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SunPosition {
    /// Above the horizon, degrees.
    pub altitude_deg: f64,
    /// Clockwise from north (east 90°, south 180°), degrees.
    pub azimuth_deg: f64,
}

/// A site, a day and a clock time.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SiteTime {
    /// North positive, degrees.
    pub latitude_deg: f64,
    /// East positive, degrees.
    pub longitude_deg: f64,
    /// Day of the year, 1 on 1 January.
    pub day_of_year: u32,
    /// Local standard time, hours from midnight.
    pub hours: f64,
    /// The time zone, hours east of UTC.
    pub timezone_h: f64,
}

/// The day of the year (1–366) of a Gregorian date; `None` for an impossible date.
pub fn day_of_year(year: i32, month: u32, day: u32) -> Option<u32> {
    let leap = (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
    let lengths = [31, if leap { 29 } else { 28 }, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31];
    let length = *lengths.get(month.checked_sub(1)? as usize)?;
    (1..=length).contains(&day).then(|| lengths[..month as usize - 1].iter().sum::<u32>() + day)
}

/// The solar declination, radians, and the equation of time, minutes, at fractional year `g`.
pub fn declination_and_equation_of_time(g: f64) -> (f64, f64) {
    let declination = 0.006918 - 0.399912 * g.cos() + 0.070257 * g.sin() - 0.006758 * (2.0 * g).cos()
        + 0.000907 * (2.0 * g).sin()
        - 0.002697 * (3.0 * g).cos()
        + 0.00148 * (3.0 * g).sin();
    let equation = 229.18
        * (0.000075 + 0.001868 * g.cos()
            - 0.032077 * g.sin()
            - 0.014615 * (2.0 * g).cos()
            - 0.040849 * (2.0 * g).sin());
    (declination, equation)
}

impl SiteTime {
    /// The sun's position at this site and time.
    pub fn sun(&self) -> SunPosition {
        let g = std::f64::consts::TAU * (self.day_of_year as f64 - 1.0 + (self.hours - 12.0) / 24.0) / 365.0;
        let (delta, equation) = declination_and_equation_of_time(g);
        let offset = equation + 4.0 * self.longitude_deg - 60.0 * self.timezone_h;
        let solar_minutes = self.hours * 60.0 + offset;
        let omega = (solar_minutes / 4.0 - 180.0).to_radians();
        let phi = self.latitude_deg.to_radians();
        let east = -delta.cos() * omega.sin();
        let north = delta.sin() * phi.cos() - delta.cos() * phi.sin() * omega.cos();
        let up = delta.sin() * phi.sin() + delta.cos() * phi.cos() * omega.cos();
        SunPosition {
            altitude_deg: up.clamp(-1.0, 1.0).asin().to_degrees(),
            azimuth_deg: east.atan2(north).to_degrees().rem_euclid(360.0),
        }
    }
}

impl SunPosition {
    /// The unit world direction towards the sun, with `up` = +y and `north` a unit
    /// horizontal world vector (east is `north × up`).
    pub fn direction(&self, north: DVec3) -> DVec3 {
        let east = north.cross(DVec3::Y);
        let (h, a) = (self.altitude_deg.to_radians(), self.azimuth_deg.to_radians());
        (h.cos() * (a.cos() * north + a.sin() * east) + h.sin() * DVec3::Y).normalize()
    }
}
