"""Block Jacobi by part inside FGMRES (issue 36, point 4; docs/petsc.md, "Block Jacobi by
part"): `(I − K) L = L0` solved by FGMRES(m) on the whole factored operator, preconditioned
by `M⁻¹ r = [(I − K_pp)⁻¹ r_p]_p`, the diagonal blocks of part_blocks.py.

The preconditioner is a PCSHELL: each rank solves the blocks of its own parts, each by an
inner GMRES on the shell `I − K_pp` (`COMM_SELF`, no preconditioner, zero initial guess,
stopping at `‖r‖ ≤ inner · ‖r_p‖`), with no communication. Inner solves to a tolerance are
not the same linear map from one application to the next, hence FGMRES outside, which
allows a preconditioner that changes between iterations (right preconditioning: the
residual it watches is the true one). The default inner tolerance is the square root of
the outer one: with one part (the block is the whole operator) the first outer iteration
leaves about `inner · ‖r_0‖` and the second `inner² · ‖r_0‖ ≤ tol · ‖L0‖`, two iterations.

As the other solvers (solvers.py): `x_0 = L0` and the stop at `‖r‖₂ ≤ tol·‖L0‖₂`.
"""

from petsc4py import PETSc

from solvers import Run, timed_solve


class ByPart:
    """The PCSHELL context: applies the inverse of every local block by an inner GMRES."""

    def __init__(self, blocks, offset, cells, inner, max_iterations):
        self.blocks, self.offset, self.cells = blocks, offset, cells
        self.inner_iterations = 0
        self.ksps = [_inner(b.A, inner, max_iterations) for b in blocks]
        self.rhs = [b.A.createVecRight() for b in blocks]
        self.out = [b.A.createVecLeft() for b in blocks]

    def apply(self, pc, x, y):
        xs, ys = x.getArray(readonly=True), y.getArray()
        for b, ksp, r, z in zip(self.blocks, self.ksps, self.rhs, self.out):
            rows = slice((b.first - self.offset) * self.cells, (b.last - self.offset) * self.cells)
            r.getArray()[:] = xs[rows]
            ksp.solve(r, z)
            self.inner_iterations += ksp.getIterationNumber()
            ys[rows] = z.getArray(readonly=True)

    def destroy(self, pc):
        """Frees the inner solvers and their vectors with the PC (petsc4py calls it)."""
        for obj in self.ksps + self.rhs + self.out:
            obj.destroy()


def _inner(A, inner, max_iterations):
    ksp = PETSc.KSP().create(comm=PETSc.COMM_SELF)
    ksp.setOptionsPrefix("inner_")
    ksp.setOperators(A)
    ksp.setType("gmres")
    ksp.getPC().setType("none")
    ksp.setTolerances(rtol=inner, atol=0.0, max_it=max_iterations)
    ksp.setFromOptions()
    return ksp


def solve(count, A, L0, blocks, offset, cells, tolerance, inner, max_iterations, restart=30):
    """Solves `A x = L0` by FGMRES(`restart`) preconditioned by the local `blocks` (this
    rank's leaves start at leaf `offset`, `cells` unknowns each); the `Run` (method
    `bjacobi:COUNT`) and the inner iterations of all ranks."""
    scale = L0.norm()
    comm = A.getComm()
    context = ByPart(blocks, offset, cells, inner, max_iterations)
    ksp = PETSc.KSP().create(comm=comm)
    ksp.setOptionsPrefix("bjacobi_")
    ksp.setOperators(A)
    ksp.setType("fgmres")
    ksp.setGMRESRestart(restart)
    pc = ksp.getPC()
    pc.setType("python")
    pc.setPythonContext(context)
    ksp.setPCSide(PETSc.PC.Side.RIGHT)
    ksp.setInitialGuessNonzero(True)
    ksp.setTolerances(rtol=0.0, atol=tolerance * scale, divtol=1e10, max_it=max_iterations)
    ksp.setConvergenceHistory(length=max_iterations + 1, reset=True)
    ksp.setFromOptions()
    x, seconds, r = timed_solve(ksp, A, L0)
    inner_total = summed(context.inner_iterations, comm)
    run = Run(
        method=f"bjacobi:{count}",
        x=x,
        iterations=ksp.getIterationNumber(),
        seconds=seconds,
        reason=int(ksp.getConvergedReason()),
        history=[h / scale for h in ksp.getConvergenceHistory()],
        residual=r.norm() / scale,
        solver=f"fgmres({restart}), pc block Jacobi by {count} parts (inner gmres to {inner:.0e})",
    )
    for obj in (ksp, r):
        obj.destroy()
    return run, inner_total


def summed(value, comm):
    """`value` summed over the ranks of `comm`."""
    v = PETSc.Vec().createMPI((1, PETSc.DECIDE), comm=comm)
    v.setArray([float(value)])
    return v.sum()
