//! Refinement iterated with the solve (`design.md` §3b, "Oracle": solve, refine where the
//! current field says it matters, solve again). The solver is the caller's (the kernel does
//! not know the methods): it solves `x = b + K x` for a right-hand side `b`. After a pass the
//! previous field, prolonged to the new leaves, is the warm start `x0`: the correction
//! `δ = r + K δ` with `r = L0 + K x0 − x0` is solved and `x = x0 + δ`. The solver gets the
//! factor `‖L0‖/‖r‖` by which it may relax its relative tolerance for the same absolute one.

use super::kernel::Hierarchy;
use super::operator::Operator;
use std::time::Instant;

/// The caller's solver: `x = b + K x` for the operator and right-hand side `b`, with the
/// factor by which it may relax its relative tolerance.
pub type Solver<'a, E> = dyn FnMut(&Operator, &[f64], f64) -> Result<Vec<f64>, E> + 'a;

/// Solves, refines and solves again until a pass refines nothing or `options.passes`
/// passes ran; returns the field on the final leaves and the final operator.
pub fn iterate<E>(hierarchy: &mut Hierarchy, solve: &mut Solver<E>) -> Result<(Vec<f64>, Operator), E> {
    let mut operator = hierarchy.operator();
    let l0 = hierarchy.source();
    let start = Instant::now();
    let mut x = solve(&operator, &l0, 1.0)?;
    hierarchy.record_solve(start.elapsed().as_secs_f64());
    while hierarchy.history().len() < hierarchy.options().passes && hierarchy.refine(&x) > 0 {
        let start = Instant::now();
        let next = hierarchy.operator();
        let x0 = hierarchy.prolong(&operator, &x);
        let l0 = hierarchy.source();
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
    Ok((x, operator))
}

fn norm(v: &[f64]) -> f64 {
    v.iter().map(|x| x * x).sum::<f64>().sqrt()
}
