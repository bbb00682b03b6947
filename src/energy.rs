//! Energy balance of a solved field, in lumens.
//!
//! Per patch: emitted `Φe = A Σ_k μ_k L0(k)`, outgoing `Φ = A Σ_k μ_k L(k)`, incident
//! `A E` with `E = π Σ_d (G x)_d`, absorbed `A π Σ_d (G x)_d (1 − a(d) − t(d))` with `a` and `t`
//! the material's directional reflectance and transmittance. Escaped flux is what leaves the surfaces and arrives
//! nowhere, `Σ Φ − Σ A E`. The imbalance `Φe − absorbed − escaped` is the flux-weighted
//! residual of the solve: zero for an exact solution of a conservative kernel.

use crate::geometry::Mesh;
use crate::kernel::Kernel;

/// Fluxes of a solution, lm.
#[derive(Debug, Clone, PartialEq)]
pub struct EnergyBalance {
    pub emitted: f64,
    pub absorbed: f64,
    pub escaped: f64,
    /// `emitted − absorbed − escaped`.
    pub imbalance: f64,
    /// Emitted flux of each surface.
    pub surface_emitted: Vec<f64>,
    /// Absorbed flux of each surface.
    pub surface_absorbed: Vec<f64>,
}

impl EnergyBalance {
    pub fn of(mesh: &Mesh, kernel: &Kernel, l0: &[f64], x: &[f64], surfaces: usize) -> EnergyBalance {
        let k = kernel.cells();
        let cells = kernel.directions.cells();
        let mut gx = vec![0.0; x.len()];
        kernel.apply_transport(x, &mut gx);
        let mut b = EnergyBalance {
            emitted: 0.0,
            absorbed: 0.0,
            escaped: 0.0,
            imbalance: 0.0,
            surface_emitted: vec![0.0; surfaces],
            surface_absorbed: vec![0.0; surfaces],
        };
        let (mut outgoing, mut incident) = (0.0, 0.0);
        for (i, p) in mesh.patches.iter().enumerate() {
            let block = &kernel.blocks[kernel.patch_material[i] as usize];
            let range = i * k..(i + 1) * k;
            let weighted = |v: &[f64]| p.area * v.iter().zip(cells).map(|(l, c)| l * c.projected).sum::<f64>();
            let emitted = weighted(&l0[range.clone()]);
            outgoing += weighted(&x[range.clone()]);
            incident += p.area * std::f64::consts::PI * gx[range.clone()].iter().sum::<f64>();
            let absorbed: f64 = (0..k)
                .map(|d| {
                    let (reflected, transmitted) = block.albedo(d, &kernel.directions);
                    p.area * std::f64::consts::PI * gx[i * k + d] * (1.0 - reflected - transmitted)
                })
                .sum();
            b.surface_emitted[p.surface as usize] += emitted;
            b.surface_absorbed[p.surface as usize] += absorbed;
        }
        b.emitted = b.surface_emitted.iter().sum();
        b.absorbed = b.surface_absorbed.iter().sum();
        b.escaped = outgoing - incident;
        b.imbalance = b.emitted - b.absorbed - b.escaped;
        b
    }
}
