//! Refinement iterated with the solve (`docs/design.md` §3b, "Oracle": solve, refine where the
//! current field says it matters, solve again). The source term and the solver are the
//! caller's (the kernel knows neither luminaires nor methods): `source` gives `L0` on the
//! current leaves (and may split leaves first, e.g. along the luminaires' shadows), `solve`
//! solves `x = b + K x` for a right-hand side `b`. After a pass the previous field,
//! prolonged to the new leaves, is the warm start `x0`: the correction `δ = r + K δ` with
//! `r = L0 + K x0 − x0` is solved and `x = x0 + δ`. The solver gets the factor `‖L0‖/‖r‖`
//! by which it may relax its relative tolerance for the same absolute one.

use super::kernel::Hierarchy;
use super::operator::Operator;
use std::time::Instant;

/// The caller's solver: `x = b + K x` for the operator and right-hand side `b`, with the
/// factor by which it may relax its relative tolerance.
pub type Solver<'a, E> = dyn FnMut(&Operator, &[f64], f64) -> Result<Vec<f64>, E> + 'a;

/// The caller's source term: `L0` on the leaves of the hierarchy (`x[leaf·K + k]`), after
/// any splits of leaves it makes.
pub type SourceTerm<'a, E> = dyn FnMut(&mut Hierarchy) -> Result<Vec<f64>, E> + 'a;

/// The field on the final leaves, the final operator and its source term.
pub struct Iterated {
    /// The solved field on the final leaves, `x[leaf·K + k]`, cd/m².
    pub x: Vec<f64>,
    /// The operator on the final leaves.
    pub operator: Operator,
    /// The source term on the final leaves, cd/m².
    pub l0: Vec<f64>,
}

/// Solves, refines and solves again until a pass refines nothing or `options.passes`
/// passes ran.
pub fn iterate<E>(hierarchy: &mut Hierarchy, source: &mut SourceTerm<E>, solve: &mut Solver<E>) -> Result<Iterated, E> {
    let mut l0 = source(hierarchy)?;
    let mut operator = hierarchy.operator();
    let start = Instant::now();
    let mut x = solve(&operator, &l0, 1.0)?;
    hierarchy.record_solve(start.elapsed().as_secs_f64());
    while hierarchy.history().len() < hierarchy.options().passes && hierarchy.refine(&x) > 0 {
        l0 = source(hierarchy)?;
        let next = hierarchy.operator();
        let start = Instant::now();
        let x0 = hierarchy.prolong(&operator, &x);
        let mut r = vec![0.0; x0.len()];
        next.apply(&x0, &mut r);
        r.iter_mut().zip(&l0).zip(&x0).for_each(|((r, l), x)| *r += l - x);
        let scale = norm(&l0) / norm(&r);
        x = x0;
        if scale.is_finite() {
            let delta = solve(&next, &r, scale)?;
            x.iter_mut().zip(&delta).for_each(|(x, d)| *x += d);
        }
        operator = next;
        hierarchy.record_solve(start.elapsed().as_secs_f64());
    }
    Ok(Iterated { x, operator, l0 })
}

fn norm(v: &[f64]) -> f64 {
    v.iter().map(|x| x * x).sum::<f64>().sqrt()
}
