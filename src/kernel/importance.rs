//! The readings' importance (`docs/design.md` (3b.3b); Smits, Arvo & Salesin 1992): how
//! much the readings move, relative to themselves, per cd/m² of error in each unknown's
//! light. With `v` the readings' direct sensitivity to the field (each reading's
//! `∂R_k/∂x`, divided by `R_k`, the largest over the readings), the importance is the adjoint
//! solution `W = v + Kᵀ W`: an error `δ` in the light an unknown gathers reaches the
//! readings both directly and through every later bounce.

use super::operator::{Factored, Kernel};

/// Sweeps of `W ← v + Kᵀ W` at most: the importance steers refinement and needs a few
/// digits only.
const SWEEPS: usize = 60;

/// Relative change of `Σ W` at which the sweeps stop.
const SETTLED: f64 = 1e-4;

/// `W = v + Kᵀ W` by Neumann sweeps (`ρ(K) < 1` for every kernel that conserves energy),
/// stopped when the total changes by less than [`SETTLED`] of itself.
pub fn importance(kernel: &Kernel, v: &[f64]) -> Vec<f64> {
    let operator = Factored::new(kernel);
    let mut w = v.to_vec();
    let mut back = vec![0.0; v.len()];
    let mut total: f64 = w.iter().sum();
    for _ in 0..SWEEPS {
        operator.apply_transposed(&w, &mut back);
        w.iter_mut().zip(v).zip(&back).for_each(|((w, v), b)| *w = v + b);
        let next: f64 = w.iter().sum();
        let settled = (next - total).abs() <= SETTLED * next.abs();
        total = next;
        if settled {
            break;
        }
    }
    w
}
