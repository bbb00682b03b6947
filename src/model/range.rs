//! Values out of range caught where they first appear (issue 18, item 2), when the model
//! is built and before any solve: the surfaces' emission `L_e`, the luminaires' direct
//! light `D` and the source term `L0 = L_e + B·D` (`docs/design.md` §2), and the kernel
//! `K = B·G` (§3): every material block `B` and every row of `G`, both kernels' in one
//! application `G·1` (a row that holds a value not finite sums to one that is not).
//!
//! The scene's limits keep every input far below an overflow (1e20 at most); a value
//! caught here came through the library unchecked, or from a fault of the model's own
//! code. Each is reported as what it is, where it is — never as a solver's failure.

use crate::geometry::Mesh;
use crate::kernel::Transport;
use crate::luminaire::DirectLight;
use crate::material::Block;
use crate::scene::Scene;
use crate::solve::SolveError;
use thiserror::Error;

/// A value of the model that no solve can carry: not finite, or a source term whose
/// norm overflows.
#[derive(Debug, Clone, PartialEq, Error)]
#[error("value out of range: {quantity} is {value:e} at {place}, before any solve{}", why(*.value))]
pub struct OutOfRange {
    /// What holds the value (`"the source term L0"`).
    pub quantity: String,
    /// Where: patch, surface and cell, material, or luminaire.
    pub place: String,
    /// The value.
    pub value: f64,
}

fn why(value: f64) -> &'static str {
    if value.is_finite() { "; its square overflows the residual's norm" } else { "" }
}

/// Unknown `u` of `mesh` (`per_patch` unknowns each) as `patch i of surface "S", cell c`.
pub fn place(scene: &Scene, mesh: &Mesh, u: usize, per_patch: usize) -> String {
    let i = u / per_patch.max(1);
    let surface = mesh.patches.get(i).and_then(|p| scene.surfaces.get(p.surface as usize));
    let name = surface.map_or(String::from("?"), |s| format!("\"{}\"", s.name));
    format!("patch {i} of surface {name}, cell {}", u % per_patch.max(1))
}

/// The first value of `values` that is not finite, with its index.
fn first_not_finite(values: &[f64]) -> Option<(usize, f64)> {
    values.iter().position(|v| !v.is_finite()).map(|u| (u, values[u]))
}

/// The surfaces' emission, the luminaires' direct light and `L0` on `mesh` (`k` cells),
/// each finite, and `‖L0‖₂` finite.
pub fn check_source(scene: &Scene, mesh: &Mesh, direct: &DirectLight, l0: &[f64], k: usize) -> Result<(), OutOfRange> {
    let at = |u: usize, per_patch: usize| place(scene, mesh, u, per_patch);
    for (luminaire, &flux) in scene.luminaires.iter().zip(&direct.intercepted) {
        if !flux.is_finite() {
            let (quantity, place) =
                ("the flux landing on the surfaces (lm)".into(), format!("luminaire \"{}\"", luminaire.name));
            return Err(OutOfRange { quantity, place, value: flux });
        }
    }
    let checks: [(&str, &[f64], usize); 3] = [
        ("the surface's own emission L_e (cd/m²)", &mesh.emission, 1),
        ("the luminaires' direct light D (cd/m²)", &direct.arriving, k),
        ("the source term L0 (cd/m²)", l0, k),
    ];
    for (quantity, values, per_patch) in checks {
        if let Some((u, value)) = first_not_finite(values) {
            return Err(OutOfRange { quantity: quantity.into(), place: at(u, per_patch), value });
        }
    }
    if !l0.iter().map(|v| v * v).sum::<f64>().is_finite() {
        let u = (0..l0.len()).max_by(|&a, &b| l0[a].abs().total_cmp(&l0[b].abs())).unwrap_or(0);
        let quantity = format!("the source term L0 (cd/m², {} unknowns)", l0.len());
        return Err(OutOfRange { quantity, place: at(u, k), value: l0[u] });
    }
    Ok(())
}

/// Every value of every material block finite.
pub fn check_blocks(scene: &Scene, blocks: &[Block], k: usize) -> Result<(), OutOfRange> {
    for (material, block) in scene.materials.iter().zip(blocks) {
        let parts = [("reflection ρ̄", Some(block.values())), ("transmission τ̄", block.transmit_values())];
        for (what, values) in parts {
            if let Some((u, value)) = values.and_then(first_not_finite) {
                let quantity = format!("the {what} block of the material \"{}\"", material.name);
                return Err(OutOfRange { quantity, place: format!("cells ({}, {})", u / k, u % k), value });
            }
        }
    }
    Ok(())
}

/// Every row of `G` finite (by `G·1`), and the first entry that is not, in its row.
pub fn check_transport(scene: &Scene, mesh: &Mesh, g: &Transport, k: usize) -> Result<(), OutOfRange> {
    let mut sums = vec![0.0; g.rows()];
    g.apply(&vec![1.0; sums.len()], &mut sums);
    let Some((row, value)) = first_not_finite(&sums) else { return Ok(()) };
    let mut column = None;
    g.for_each_in_row(row, |c, v| {
        if column.is_none() && !v.is_finite() {
            column = Some(place(scene, mesh, c, k));
        }
    });
    let quantity = match column {
        Some(c) => format!("the form factor G to {c}"),
        None => "the row sum of the form factors G".into(),
    };
    Err(OutOfRange { quantity, place: place(scene, mesh, row, k), value })
}

/// `error` with its unknown named by patch, surface and cell when it is a value out of
/// range (`unknowns` of the solved system over the patches of `mesh`: cells or a basis's
/// coefficients).
pub fn locate(error: SolveError, scene: &Scene, mesh: &Mesh, unknowns: usize) -> SolveError {
    match error {
        SolveError::OutOfRange(mut range) => {
            range.place = Some(place(scene, mesh, range.unknown, unknowns / mesh.len().max(1)));
            SolveError::OutOfRange(range)
        }
        other => other,
    }
}
