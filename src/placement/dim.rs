//! The dimmest spots of a room: a quick backward estimate of the illuminance at each
//! candidate (`trace::trace_probes`, [`PATHS`] paths, ±5–15 %), the lowest kept. Drawn
//! uniformly over the surfaces, `count` out of `20 × count` candidates are the dimmest 5 %
//! of the room's area, to the estimate's noise.

use super::around::Spot;
use crate::scene::Probe;
use crate::trace::{TraceOptions, World, trace_probes};

/// Paths per candidate of the quick estimate.
pub const PATHS: usize = 256;

/// The `count` spots of `spots` with the lowest estimated illuminance, dimmest first.
pub fn dimmest(world: &World, spots: &[Spot], count: usize, seed: u64) -> Vec<Spot> {
    let probes: Vec<Probe> = spots.iter().map(|s| Probe::point("candidate", s.probe(), s.normal())).collect();
    let options = TraceOptions { seed, max_order: None };
    let readings = trace_probes(world, &probes, PATHS, &options, &|_| {});
    let mut order: Vec<usize> = (0..spots.len()).collect();
    order.sort_by(|&a, &b| readings[a].illuminance.0.total_cmp(&readings[b].illuminance.0));
    order.into_iter().take(count).map(|i| spots[i]).collect()
}
