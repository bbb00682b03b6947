//! Material blocks `ρ̄(k,d)` (src/material): energy, closed forms, comparison with independent
//! quadrature, and reciprocity of the cell-averaged luminance factors. Measured figures are
//! printed with `--nocapture` and quoted in docs/materials.md.

mod energy;
mod ggx;
mod lobe;
mod phong;
mod quadrature;
mod reciprocity;

use std::collections::HashMap;
use std::sync::{Arc, Mutex, OnceLock};
use ugo::directions::DirectionSet;
use ugo::material::Block;
use ugo::material::MaterialModel;

pub const LAMBERT: MaterialModel = MaterialModel::Lambert { reflectance: 0.6, transmittance: 0.3 };
pub const MIRROR: MaterialModel = MaterialModel::Mirror { reflectance: 0.9 };

/// A Phong material with `k_d + k_s = 1`, the worst case for energy.
pub fn phong(exponent: f64) -> MaterialModel {
    MaterialModel::Phong { diffuse: 0.2, specular: 0.8, exponent }
}

/// A GGX material with `k_d + k_s = 1`.
pub fn ggx(roughness: f64) -> MaterialModel {
    MaterialModel::Ggx { diffuse: 0.1, specular: 0.9, roughness }
}

/// The sets every material is tested on: `K` = 1, 16, 64 and Klems (145).
pub fn standard_sets() -> Vec<DirectionSet> {
    vec![DirectionSet::single(), DirectionSet::hemisphere(16), DirectionSet::hemisphere(64), DirectionSet::klems()]
}

/// Every (material, direction set) pair of the tests. A glossy block costs about 2 s at
/// `K = 64` and 5 s at 145 (lobe sampling), so one parameter of each glossy model covers
/// all the standard sets, the extremes (`n = 1`, `α = 0.1`) go to `K = 64`, and the rest to 16.
pub fn matrix() -> Vec<(MaterialModel, Vec<DirectionSet>)> {
    let upto = |k: usize| standard_sets().into_iter().filter(|s| s.len() <= k).collect::<Vec<_>>();
    let mut cheap = standard_sets();
    cheap.extend([7, 145, 500].map(DirectionSet::hemisphere));
    cheap.push(DirectionSet::tregenza());
    vec![
        (LAMBERT, cheap.clone()),
        (MaterialModel::Lambert { reflectance: 0.8, transmittance: 0.0 }, cheap.clone()),
        (MIRROR, cheap),
        (phong(100.0), standard_sets()),
        (phong(1.0), upto(64)),
        (phong(10.0), upto(16)),
        (phong(1000.0), upto(16)),
        (ggx(0.3), standard_sets()),
        (ggx(0.1), upto(64)),
        (ggx(0.6), upto(16)),
    ]
}

/// `MaterialModel::block`, built once per (material, set) for all the tests of the crate.
pub fn block(model: &MaterialModel, set: &DirectionSet) -> Arc<Block> {
    type Cache = Mutex<HashMap<String, Arc<OnceLock<Arc<Block>>>>>;
    static CACHE: OnceLock<Cache> = OnceLock::new();
    let key = format!("{model:?} on {}", set.name());
    let slot = CACHE.get_or_init(Default::default).lock().unwrap().entry(key).or_default().clone();
    slot.get_or_init(|| Arc::new(model.block(set))).clone()
}

/// The rings of a set, `(cos_bottom, cos_top, cells)`: every cell of a ring has the same
/// albedo for an isotropic material.
pub fn rings(set: &DirectionSet) -> Vec<(f64, f64, Vec<usize>)> {
    let mut out: Vec<(f64, f64, Vec<usize>)> = Vec::new();
    for k in 0..set.len() {
        let (bottom, top, _, _) = set.bounds(k);
        match out.last_mut() {
            Some((b, t, cells)) if *b == bottom && *t == top => cells.push(k),
            _ => out.push((bottom, top, vec![k])),
        }
    }
    out
}
