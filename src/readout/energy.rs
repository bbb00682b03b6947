//! Energy balance of a solved field, in lumens.
//!
//! Per patch: emitted `Φe = A L_e Σ_k μ_k` (its own emission), outgoing
//! `Φ = A Σ_k μ_k L(k)`, incident `A E` with `E = π Σ_d ((G x)_d + D_d)` (light from the
//! surfaces and, directly, from the luminaires), absorbed
//! `A π Σ_d ((G x)_d + D_d) (1 − a(d) − t(d))` with `a` and `t` the material's directional
//! reflectance and transmittance. A luminaire emits its flux (parallel light: what lands
//! on the patches); what of it lands nowhere escapes, as does what leaves the surfaces and
//! arrives nowhere, `Σ Φ − Σ A π Σ_d (G x)_d`. The imbalance `emitted − absorbed − escaped`
//! is the flux-weighted residual of the solve: zero for an exact solution of a
//! conservative kernel.

use super::illuminance::{arriving, patch_illuminance};
use crate::model::Model;
use std::f64::consts::PI;

/// Fluxes of a solution, lm.
#[derive(Debug, Clone, PartialEq)]
pub struct EnergyBalance {
    /// Surfaces' own emission plus the luminaires' flux.
    pub emitted: f64,
    /// Flux absorbed by the surfaces.
    pub absorbed: f64,
    /// Flux no patch receives: what the surfaces send beyond the patches (through openings,
    /// onto backs of one-sided surfaces) plus the luminaires' light that misses them.
    pub escaped: f64,
    /// `emitted − absorbed − escaped`.
    pub imbalance: f64,
    /// Emitted flux of each surface.
    pub surface_emitted: Vec<f64>,
    /// Absorbed flux of each surface.
    pub surface_absorbed: Vec<f64>,
    /// Flux leaving each luminaire (parallel light: the flux landing on the patches).
    pub luminaire_emitted: Vec<f64>,
}

impl EnergyBalance {
    /// The balance of the solution `x` of `model`, with the per-surface fluxes of its
    /// `surfaces` surfaces.
    pub fn of(model: &Model, x: &[f64], surfaces: usize) -> EnergyBalance {
        let (mesh, kernel) = (&model.mesh, &model.kernel);
        let k = kernel.cells();
        let cells = kernel.directions.cells();
        let projected: f64 = cells.iter().map(|c| c.projected).sum();
        let direct = &model.direct;
        let light = arriving(model, x);
        let from_luminaires = patch_illuminance(&direct.arriving, k);
        let luminaire_emitted: Vec<f64> =
            model.sources.iter().zip(&direct.intercepted).map(|(s, &landed)| s.flux().unwrap_or(landed)).collect();
        let mut b = EnergyBalance {
            emitted: 0.0,
            absorbed: 0.0,
            escaped: 0.0,
            imbalance: 0.0,
            surface_emitted: vec![0.0; surfaces],
            surface_absorbed: vec![0.0; surfaces],
            luminaire_emitted,
        };
        let (mut outgoing, mut from_surfaces) = (0.0, 0.0);
        for (i, p) in mesh.patches.iter().enumerate() {
            let block = &kernel.blocks[kernel.patch_material[i] as usize];
            let range = i * k..(i + 1) * k;
            outgoing += p.exposed * x[range.clone()].iter().zip(cells).map(|(l, c)| l * c.projected).sum::<f64>();
            from_surfaces += p.exposed * (PI * light[range].iter().sum::<f64>() - from_luminaires[i]);
            let absorbed: f64 = (0..k)
                .map(|d| {
                    let (reflected, transmitted) = block.albedo(d, &kernel.directions);
                    p.exposed * PI * light[i * k + d] * (1.0 - reflected - transmitted)
                })
                .sum();
            b.surface_emitted[p.surface as usize] += p.exposed * mesh.emission[i] * projected;
            b.surface_absorbed[p.surface as usize] += absorbed;
        }
        let lost_by_luminaires: f64 =
            b.luminaire_emitted.iter().zip(&direct.intercepted).map(|(emitted, landed)| emitted - landed).sum();
        b.emitted = b.surface_emitted.iter().sum::<f64>() + b.luminaire_emitted.iter().sum::<f64>();
        b.absorbed = b.surface_absorbed.iter().sum();
        b.escaped = outgoing - from_surfaces + lost_by_luminaires;
        b.imbalance = b.emitted - b.absorbed - b.escaped;
        b
    }
}
