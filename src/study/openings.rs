//! A scene nearly closed (issue 18, item 4): light escaping through an opening that is
//! small against the surfaces around it is more likely a missing wall or a gap between
//! surfaces than a window, and is warned about; so is light that the hierarchy's links
//! lose themselves, which is no opening.
//!
//! The opening's area comes from reciprocity. An opening of area `A_o`, seen from inside,
//! sees nothing but the scene's surfaces, so `Σ_j A_j F_(j→o) = A_o Σ_j F_(o→j) = A_o`; the
//! kernel gives `F_(j→o)` as `1 − t_j`, `t_j` the closure of `j` (`kernel::closure_shares`,
//! per cell weighted by `μ_m/π`), summed over the columns that send light (a face pressed
//! against another sends none), and the flux escaping through the openings as
//! `Σ Φ_j (1 − t_j)` (the luminaires' light that lands nowhere is not counted: a lamp above
//! a plane). The rest of the escaped flux, `Σ Φ_j (t_j − s_j)` with `s_j` the columns' sent
//! shares (`kernel::sent_shares`), is the hierarchy's links' own loss (0 for the uniform
//! kernel, whose closures are its sent shares), warned about when beyond [`LOST`] of the
//! emitted flux. Warned when
//! the area is below [`SMALL`] of the surfaces' area while more than [`ESCAPING`] of the
//! emitted flux escapes through it. A scene open by design has a large opening (the
//! Cornell box's open front: about a sixth of its surfaces).

use crate::io::Warning;
use crate::model::Model;
use crate::readout::energy::EnergyBalance;
use crate::scene::Scene;
use std::f64::consts::PI;

/// Largest opening, as a share of the surfaces' area, taken for a gap.
pub const SMALL: f64 = 0.03;
/// Share of the emitted flux escaping above which a small opening is reported.
pub const ESCAPING: f64 = 0.02;
/// Share of the emitted flux lost by the kernel's own columns above which it is reported:
/// a lighting design reads illuminance to about a percent.
pub const LOST: f64 = 0.01;

/// The warning for light escaping through a small opening, if any; `closures` are the
/// closures of the kernel's columns' patches (`kernel::closure_shares`), `x` the solved field.
pub fn small_opening(
    scene: &Scene,
    model: &Model,
    x: &[f64],
    energy: &EnergyBalance,
    closures: &[f64],
) -> Option<Warning> {
    let (k, cells) = (model.kernel.cells(), model.kernel.directions.cells());
    let mut leak = vec![0.0; scene.surfaces.len()];
    let mut escaping = 0.0;
    for (c, s) in closures.iter().enumerate() {
        let p = &model.mesh.patches[c / k];
        if x[c] > 0.0 {
            let share = p.exposed * cells[c % k].projected / PI * (1.0 - s).max(0.0);
            leak[p.surface as usize] += share;
            escaping += PI * share * x[c];
        }
    }
    let opening: f64 = leak.iter().sum();
    let surfaces: f64 = model.mesh.patches.iter().map(|p| p.area).sum();
    if escaping <= ESCAPING * energy.emitted || opening >= SMALL * surfaces {
        return None;
    }
    let mut order: Vec<usize> = (0..leak.len()).filter(|&i| leak[i] > 0.0).collect();
    order.sort_by(|&a, &b| leak[b].total_cmp(&leak[a]));
    let seen_by = order.iter().take(3).map(|&i| scene.surfaces[i].name.clone()).collect();
    Some(Warning::SmallOpening { escaping, emitted: energy.emitted, opening, surfaces, seen_by })
}

/// The warning for light lost by the kernel's own columns, if beyond [`LOST`] of the
/// emitted flux: `Σ Φ_c (t_c − s_c)` over the columns `c` with `sent` their sent shares and
/// `closures` their patches' closures.
pub fn kernel_loss(
    model: &Model,
    x: &[f64],
    energy: &EnergyBalance,
    sent: &[f64],
    closures: &[f64],
) -> Option<Warning> {
    let flux = outgoing(model, x);
    let lost: f64 = (0..sent.len()).map(|c| flux(c) * (closures[c] - sent[c])).sum();
    (lost > LOST * energy.emitted).then_some(Warning::KernelLoss { lost, emitted: energy.emitted })
}

/// Each column's outgoing flux `Φ_c = A_j μ_m max(x_c, 0)`, lm (`c = j·K + m`, `A_j` the
/// exposed area), as the escaped flux `Σ Φ (1 − s)` weighs it.
pub fn outgoing<'a>(model: &'a Model, x: &'a [f64]) -> impl Fn(usize) -> f64 + 'a {
    let (k, cells) = (model.kernel.cells(), model.kernel.directions.cells());
    move |c| model.mesh.patches[c / k].exposed * cells[c % k].projected * x[c].max(0.0)
}
