//! Normalized modified Phong (Lafortune & Willems 1994): `ρ = k_d + k_s (n+2)/2 cosⁿα`.
//! The glossy lobe is integrated by sampling `cosⁿα` around the mirror direction
//! (pdf `(n+1)/(2π) cosⁿα`) on a fixed stratified grid, so exponents up to 10⁵ are resolved.

use super::cells::{Accumulator, mirror, stratified};
use crate::directions::DirectionSet;
use glam::DVec3;
use std::f64::consts::{PI, TAU};

const STRATA_IN: usize = 12;
const STRATA_LOBE: usize = 48;

pub fn block(diffuse: f64, specular: f64, exponent: f64, directions: &DirectionSet) -> Vec<f64> {
    let k = directions.len();
    let mut acc = Accumulator::new(k);
    for d in 0..k {
        for (l_in, w_in) in stratified(directions, d, STRATA_IN) {
            let r = mirror(l_in);
            let (t, b) = r.any_orthonormal_pair();
            for i in 0..STRATA_LOBE {
                let u = (i as f64 + 0.5) / STRATA_LOBE as f64;
                let cos_a = u.powf(1.0 / (exponent + 1.0));
                let sin_a = (1.0 - cos_a * cos_a).max(0.0).sqrt();
                for j in 0..STRATA_LOBE {
                    let phi = TAU * (j as f64 + 0.5) / STRATA_LOBE as f64;
                    let l: DVec3 = (t * phi.cos() + b * phi.sin()) * sin_a + r * cos_a;
                    if l.z <= 0.0 {
                        continue;
                    }
                    // ρ cosθ / pdf = k_s (n+2)/2 · 2π/(n+1) · cosθ
                    let value = specular * PI * (exponent + 2.0) / (exponent + 1.0) * l.z;
                    acc.add(directions.lookup(l), d, value * w_in / (STRATA_LOBE * STRATA_LOBE) as f64);
                }
            }
        }
    }
    let mut block = acc.finish(directions);
    block.iter_mut().for_each(|v| *v += diffuse);
    block
}
