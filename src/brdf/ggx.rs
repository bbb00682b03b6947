//! GGX microfacet reflection (Walter et al. 2007) with height-correlated Smith masking
//! (Heitz 2014) and no Fresnel factor, plus a diffuse part:
//! `ρ = k_d + k_s π D(h) G₂(l,l') / (4 cosθ cosθ')`. The specular part is integrated by
//! sampling visible-normal-free `D(h) cosθ_h` on a fixed stratified grid and reflecting.

use super::cells::{Accumulator, stratified};
use crate::directions::DirectionSet;
use glam::DVec3;
use std::f64::consts::{PI, TAU};

const STRATA_IN: usize = 12;
const STRATA_LOBE: usize = 48;

pub fn block(diffuse: f64, specular: f64, alpha: f64, directions: &DirectionSet) -> Vec<f64> {
    let k = directions.len();
    let mut acc = Accumulator::new(k);
    let a2 = alpha * alpha;
    let lambda = |c: f64| (-1.0 + (1.0 + a2 * (1.0 - c * c) / (c * c)).sqrt()) / 2.0;
    for d in 0..k {
        for (l_in, w_in) in stratified(directions, d, STRATA_IN) {
            for i in 0..STRATA_LOBE {
                let u = (i as f64 + 0.5) / STRATA_LOBE as f64;
                let cos_h = ((1.0 - u) / (1.0 + (a2 - 1.0) * u)).sqrt();
                let sin_h = (1.0 - cos_h * cos_h).max(0.0).sqrt();
                for j in 0..STRATA_LOBE {
                    let phi = TAU * (j as f64 + 0.5) / STRATA_LOBE as f64;
                    let h = DVec3::new(sin_h * phi.cos(), sin_h * phi.sin(), cos_h);
                    let l = 2.0 * l_in.dot(h) * h - l_in;
                    if l.z <= 0.0 || l_in.dot(h) <= 0.0 {
                        continue;
                    }
                    // pdf(l) = D cos_h / (4 |l·h|); ρ cosθ / pdf = k_s π G₂ |l·h| / (cosθ' cos_h)
                    let g2 = 1.0 / (1.0 + lambda(l.z) + lambda(l_in.z));
                    let value = specular * PI * g2 * l_in.dot(h) / (l_in.z * cos_h);
                    acc.add(directions.lookup(l), d, value * w_in / (STRATA_LOBE * STRATA_LOBE) as f64);
                }
            }
        }
    }
    let mut block = acc.finish(directions);
    block.iter_mut().for_each(|v| *v += diffuse);
    block
}
