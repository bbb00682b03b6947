//! The hierarchical operator as the `LinOp` every solver takes (`design.md` §3b, "Apply K
//! x": Neumann with its reflection orders, GMRES, BiCGSTAB). Moves to `solve/` with `LinOp`.

use super::operator::Operator;

impl crate::kernel::LinOp for Operator {
    fn dim(&self) -> usize {
        Operator::dim(self)
    }

    fn apply(&self, x: &[f64], y: &mut [f64]) {
        Operator::apply(self, x, y)
    }
}
