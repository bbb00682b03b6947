//! The hierarchical kernel refined with the solve (`docs/design.md` §3b, "Oracle": solve,
//! refine where the current field says it matters, solve again). The source term and the
//! solver are the caller's (the kernel knows neither luminaires nor methods): `source`
//! gives `L0` on the current leaves (and may split leaves first, e.g. along the
//! luminaires' shadows), `solve` solves `x = b + K x` for a right-hand side `b` with the
//! kernel `K = B·G` on the current leaves ([`Kernel::on_leaves`]). After a pass the previous
//! field, prolonged to the new leaves, is the warm start `x0`: the correction
//! `δ = r + K δ` with `r = L0 + K x0 − x0` is solved and `x = x0 + δ`. The solver gets the
//! factor `‖L0‖/‖r‖` by which it may relax its relative tolerance for the same absolute
//! one. Each pass's record is made here, from the work the hierarchy counts.

use super::hierarchy::{Hierarchy, Pass, Stopped, Work};
use super::importance::importance;
use super::operator::{Factored, Kernel};
use crate::geometry::Mesh;
use crate::progress::Progress;
use std::time::Instant;

/// The caller's solver: `x = b + K x` for the kernel and right-hand side `b`, with the
/// factor by which it may relax its relative tolerance.
pub type Solver<'a, E> = dyn FnMut(&Kernel, &[f64], f64) -> Result<Vec<f64>, E> + 'a;

/// The caller's source term: `L0` on the leaves of the hierarchy (`x[leaf·K + k]`), after
/// any splits of leaves it makes.
pub type SourceTerm<'a, E> = dyn FnMut(&mut Hierarchy) -> Result<Vec<f64>, E> + 'a;

/// The caller's readings: for the field `x` on the current leaves of the hierarchy, each
/// unknown's direct share of the readings, `max_k (∂R_k/∂x)/R_k` (none: no readings steer
/// the refinement).
pub type Readings<'a, E> = dyn FnMut(&Hierarchy, &[f64]) -> Result<Option<Vec<f64>>, E> + 'a;

/// The field on the final leaves, the kernel there, its source term, and the passes.
pub struct Refined {
    /// The solved field on the final leaves, `x[leaf·K + k]`, cd/m².
    pub x: Vec<f64>,
    /// The kernel on the final leaves.
    pub kernel: Kernel,
    /// The final leaves as a mesh.
    pub leaves: Mesh,
    /// The source term on the final leaves, cd/m².
    pub l0: Vec<f64>,
    /// One record per pass, the initial linking first.
    pub history: Vec<Pass>,
}

/// Solves, refines and solves again until a pass refines nothing or `options.passes`
/// passes ran, each pass steered by the `readings`' importance (3b.3b); `progress` hears
/// of each pass's linking and operator.
pub fn refine_with_solves<E: From<Stopped>>(
    hierarchy: &mut Hierarchy,
    source: &mut SourceTerm<E>,
    solve: &mut Solver<E>,
    readings: &mut Readings<E>,
    progress: &dyn Progress,
) -> Result<Refined, E> {
    let mut before = Work::default();
    let mut l0 = source(hierarchy)?;
    let (mut kernel, mut leaves) = balanced(hierarchy, 0, progress)?;
    let start = Instant::now();
    let mut x = solve(&kernel, &l0, 1.0)?;
    let mut history = vec![record(hierarchy, &kernel, 0, 1, &mut before, start)];
    while history.len() < hierarchy.options().passes {
        let solved_on = hierarchy.tree().leaves();
        let importance = readings(hierarchy, &x)?.map(|v| importance(&kernel, &v));
        let refined = hierarchy.refine(&x, importance.as_deref(), progress)?;
        if refined == 0 {
            break;
        }
        // the next operator is built in this one's place: two at once would hold the push twice
        drop(kernel);
        l0 = source(hierarchy)?;
        let (next, next_leaves) = balanced(hierarchy, history.len(), progress)?;
        let start = Instant::now();
        let x0 = hierarchy.prolong(&solved_on, &x);
        let mut r = vec![0.0; x0.len()];
        Factored::new(&next).apply(&x0, &mut r);
        r.iter_mut().zip(&l0).zip(&x0).for_each(|((r, l), x)| *r += l - x);
        let scale = norm(&l0) / norm(&r);
        x = x0;
        if scale.is_finite() {
            let delta = solve(&next, &r, scale)?;
            x.iter_mut().zip(&delta).for_each(|(x, d)| *x += d);
        }
        (kernel, leaves) = (next, next_leaves);
        history.push(record(hierarchy, &kernel, history.len(), refined, &mut before, start));
    }
    hierarchy.refined();
    Ok(Refined { x, kernel, leaves, l0, history })
}

/// The kernel on the leaves (`Kernel::on_leaves`, seconds of balancing; `progress` hears of
/// its push), or the stop a signal asked for meanwhile (`crate::interrupt`).
fn balanced<E: From<Stopped>>(
    hierarchy: &mut Hierarchy,
    pass: usize,
    progress: &dyn Progress,
) -> Result<(Kernel, Mesh), E> {
    let built = Kernel::on_leaves(hierarchy, progress);
    crate::interrupt::check(|| format!("the hierarchical kernel's balancing, pass {pass}"))
        .map_err(|stop| E::from(Stopped::from(stop)))?;
    Ok(built)
}

/// The record of pass `pass`, which refined `refined` links: the work since `before`
/// (moved on to now), the hierarchy as it stands, and the solve begun at `solved`.
fn record(h: &Hierarchy, kernel: &Kernel, pass: usize, refined: usize, before: &mut Work, solved: Instant) -> Pass {
    let work = h.work();
    let record = Pass {
        pass,
        links: h.links().len(),
        refined,
        leaves: h.tree().leaves().len(),
        nodes: h.tree().len(),
        source_splits: work.splits - before.splits,
        rays: work.rays - before.rays,
        balance: kernel.g.hierarchy().and_then(|g| g.balanced()),
        epsilon: h.epsilon(),
        seconds: work.seconds - before.seconds,
        operator_seconds: work.operator_seconds - before.operator_seconds,
        solve_seconds: solved.elapsed().as_secs_f64(),
    };
    *before = work;
    record
}

fn norm(v: &[f64]) -> f64 {
    v.iter().map(|x| x * x).sum::<f64>().sqrt()
}
