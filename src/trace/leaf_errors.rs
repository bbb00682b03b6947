//! A deterministic field against a forward Monte Carlo estimate bin by bin
//! (`docs/design.md` §4): the relative errors `|x − m|/m` of the bins the estimate pins to
//! a given precision (`σ/m ≤ precision`), summarized by area: their area-weighted mean,
//! area-weighted 95th percentile and largest. Where `agreement` asks whether the two
//! agree within the estimate's noise, this says how far off the field is where the
//! estimate is good enough to tell, leaf by leaf.

/// The relative errors of the precise bins.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LeafErrors {
    /// Bins compared: a positive estimate with `σ/m` within the precision.
    pub bins: usize,
    /// Their share of the area of all bins.
    pub area_share: f64,
    /// Area-weighted mean of `|x − m|/m`.
    pub mean: f64,
    /// The smallest `|x − m|/m` below which 95 % of their area lies.
    pub p95: f64,
    /// Largest `|x − m|/m`, and its bin.
    pub largest: (f64, usize),
}

/// The bins of `values` against `mean ± error` whose relative standard error is at most
/// `precision`, each weighted by `areas` (m², one per bin); `None` when there are none.
pub fn leaf_errors(values: &[f64], mean: &[f64], error: &[f64], areas: &[f64], precision: f64) -> Option<LeafErrors> {
    let mut compared: Vec<(f64, f64, usize)> = (0..values.len())
        .filter(|&b| mean[b] > 0.0 && error[b] > 0.0 && error[b] <= precision * mean[b])
        .map(|b| ((values[b] - mean[b]).abs() / mean[b], areas[b], b))
        .collect();
    let total: f64 = areas.iter().sum();
    let area: f64 = compared.iter().map(|c| c.1).sum();
    if compared.is_empty() || area <= 0.0 {
        return None;
    }
    compared.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mean_error = compared.iter().map(|c| c.0 * c.1).sum::<f64>() / area;
    let mut below = 0.0;
    let p95 = compared.iter().find(|c| {
        below += c.1;
        below >= 0.95 * area
    });
    let &(largest, _, worst) = compared.last()?;
    Some(LeafErrors {
        bins: compared.len(),
        area_share: area / total,
        mean: mean_error,
        p95: p95.map_or(largest, |c| c.0),
        largest: (largest, worst),
    })
}
