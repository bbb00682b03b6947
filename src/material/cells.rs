//! Quadrature inside direction cells: stratified directions with their `cosθ dω` weights,
//! and the accumulation of a block from weighted (incoming, outgoing) direction pairs.

use crate::directions::DirectionSet;
use glam::DVec3;
use std::f64::consts::TAU;

/// `n × n` stratified directions of cell `k` (upper hemisphere) with weights `cosθ dω`.
pub fn stratified(directions: &DirectionSet, k: usize, n: usize) -> Vec<(DVec3, f64)> {
    let (cb, ct, p0, p1) = directions.bounds(k);
    let mut out = Vec::with_capacity(n * n);
    for i in 0..n {
        // equal steps in cos²θ give equal projected solid angle
        let (s0, s1) = (
            ct * ct + (cb * cb - ct * ct) * i as f64 / n as f64,
            ct * ct + (cb * cb - ct * ct) * (i + 1) as f64 / n as f64,
        );
        let c = (0.5 * (s0 + s1)).max(0.0).sqrt();
        let sin = (1.0 - c * c).max(0.0).sqrt();
        for j in 0..n {
            let phi = p0 + (p1 - p0) * (j as f64 + 0.5) / n as f64;
            let weight = 0.5 * (s0 - s1) * (p1 - p0) / n as f64;
            out.push((DVec3::new(sin * phi.cos(), sin * phi.sin(), c), weight));
        }
    }
    debug_assert!(p1 - p0 <= TAU + 1e-12);
    out
}

/// Mirror image of a local direction about the normal.
#[inline]
pub fn mirror(l: DVec3) -> DVec3 {
    DVec3::new(-l.x, -l.y, l.z)
}

/// Adds `weight` to the unnormalized block entry `(lookup(outgoing), d)`; `finish`
/// divides by `μ_k μ_d`.
pub struct Accumulator {
    k: usize,
    sums: Vec<f64>,
}

impl Accumulator {
    /// An empty accumulator for a block of `k × k` cells.
    pub fn new(k: usize) -> Self {
        Accumulator { k, sums: vec![0.0; k * k] }
    }

    /// Adds `weight` to the entry of outgoing cell `out` and incoming cell `d`.
    #[inline]
    pub fn add(&mut self, out: usize, d: usize, weight: f64) {
        self.sums[out * self.k + d] += weight;
    }

    /// The row-major block: every sum divided by `μ_k μ_d` of `directions`.
    pub fn finish(mut self, directions: &DirectionSet) -> Vec<f64> {
        let cells = directions.cells();
        for k in 0..self.k {
            for d in 0..self.k {
                self.sums[k * self.k + d] /= cells[k].projected * cells[d].projected;
            }
        }
        self.sums
    }
}
