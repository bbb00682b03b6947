//! Round tick values for axes and legends: steps of 1, 2 or 5 times a power of ten on a
//! linear scale, and 1, 2, 5 in every decade on a logarithmic one, so that a legend reads
//! 0, 100, 200 … lx and not 0, 112.3, 224.6 ….

/// The smallest step `{1, 2, 5} × 10^k` that divides `[lo, hi]` into at most `most` parts.
pub fn step(lo: f64, hi: f64, most: usize) -> f64 {
    let (mantissa, exponent) = parts(lo, hi, most);
    times(mantissa, exponent)
}

/// The step as `(m, k)`: `m × 10^k`, `m` of 1, 2, 5.
fn parts(lo: f64, hi: f64, most: usize) -> (f64, i32) {
    let span = (hi - lo).abs();
    if !(span.is_finite() && span > 0.0) {
        return (1.0, 0);
    }
    let raw = span / most.max(1) as f64;
    let k = raw.log10().floor() as i32;
    [(1.0, k), (2.0, k), (5.0, k), (1.0, k + 1)]
        .into_iter()
        .find(|&(m, k)| times(m, k) >= raw * (1.0 - 1e-12))
        .unwrap_or((1.0, k + 1))
}

/// `m × 10^k`, dividing for negative `k` so that `3 × 10^-1` is the double nearest 0.3.
fn times(m: f64, k: i32) -> f64 {
    if k >= 0 { m * 10f64.powi(k) } else { m / 10f64.powi(-k) }
}

/// The multiples of [`step`] within `[lo, hi]` (ends included to a relative `1e-9`).
pub fn ticks(lo: f64, hi: f64, most: usize) -> Vec<f64> {
    let (m, k) = parts(lo, hi, most);
    let s = times(m, k);
    let slack = 1e-9 * (hi - lo).abs().max(s);
    let first = ((lo - slack) / s).ceil() as i64;
    let last = ((hi + slack) / s).floor() as i64;
    (first..=last).map(|i| times(i as f64 * m, k)).collect()
}

/// The smallest multiple of [`step`] at or above `hi`: a round top for a scale from `lo`.
pub fn round_top(lo: f64, hi: f64, most: usize) -> f64 {
    let s = step(lo, hi, most);
    (hi / s - 1e-9).ceil() * s
}

/// `1, 2, 5 × 10^k` within `[lo, hi]` (`0 < lo < hi`); only the powers of ten when that
/// gives more than `most`.
pub fn log_ticks(lo: f64, hi: f64, most: usize) -> Vec<f64> {
    if !(lo > 0.0 && hi > lo && hi.is_finite()) {
        return Vec::new();
    }
    let inside = |v: &f64| *v >= lo * (1.0 - 1e-9) && *v <= hi * (1.0 + 1e-9);
    let decades = lo.log10().floor() as i32..=hi.log10().ceil() as i32;
    let all: Vec<f64> =
        decades.clone().flat_map(|k| [1.0, 2.0, 5.0].map(|m| m * 10f64.powi(k))).filter(inside).collect();
    if all.len() <= most { all } else { decades.map(|k| 10f64.powi(k)).filter(inside).collect() }
}

/// The nearest value `{1, 2, 5} × 10^k` at or above `v > 0` (`up`), or at or below it.
pub fn round_125(v: f64, up: bool) -> f64 {
    if !(v > 0.0 && v.is_finite()) {
        return v;
    }
    let decade = 10f64.powf(v.log10().floor());
    let candidates = [0.5, 1.0, 2.0, 5.0, 10.0].map(|m| m * decade);
    let tol = 1e-9 * v;
    match up {
        true => candidates.into_iter().find(|&c| c >= v - tol).unwrap_or(10.0 * decade),
        false => candidates.into_iter().rev().find(|&c| c <= v + tol).unwrap_or(decade),
    }
}

/// A tick value as text: no trailing zeros, at most three decimals, `1e-5` style when tiny
/// or huge.
pub fn tick_label(value: f64) -> String {
    let magnitude = value.abs();
    if value == 0.0 {
        "0".into()
    } else if !(1e-3..1e6).contains(&magnitude) {
        format!("{value:.0e}")
    } else {
        let text = format!("{value:.3}");
        text.trim_end_matches('0').trim_end_matches('.').to_string()
    }
}
