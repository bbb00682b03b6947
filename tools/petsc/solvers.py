"""Solving `(I − K) L = L0` with PETSc's KSP (docs/petsc.md): GMRES(m), BiCGSTAB, and a
parallel LU (MUMPS, else SuperLU_dist), set up to be comparable with ugo's own solvers
(src/solve/gmres.rs, bicgstab.rs, direct.rs):

* the initial guess is `x_0 = L0`, as ugo's (KSP's nonzero initial guess);
* no preconditioner, so the residual KSP monitors is the true one, `‖L0 − (I − K) x‖₂`,
  and GMRES's within a cycle is the Arnoldi estimate `|g_{j+1}|`, as ugo's;
* GMRES orthogonalizes by modified Gram–Schmidt, as ugo's;
* the iteration stops at `‖r‖₂ ≤ tol·‖L0‖₂` (KSP's absolute tolerance `tol·‖L0‖₂`, no
  relative one: KSP's relative test divides by `‖r_0‖`, ugo's by `‖L0‖`).

The residual history is returned relative to `‖L0‖₂`, as ugo's `/solver/residual_history`.
KSP logs one value per iteration; ugo's GMRES logs both the last estimate of a cycle and
the true residual that starts the next (check.py's `fold` puts ugo's record on KSP's axis).
"""

import time
from dataclasses import dataclass, field

from petsc4py import PETSc

# ugo's method names → KSP types.
KSP_TYPES = {"gmres": "gmres", "bicgstab": "bcgs"}


@dataclass
class Run:
    """One solve: the method as named on the command line, and what it gave."""

    method: str
    x: PETSc.Vec
    iterations: int
    seconds: float
    reason: int
    # ‖r‖₂/‖L0‖₂ per iteration (empty for the direct solver).
    history: list = field(default_factory=list)
    # ‖L0 − (I − K) x‖₂/‖L0‖₂ of the returned x.
    residual: float = float("nan")
    # The KSP and PC types and, for LU, the factorization package.
    solver: str = ""


def parse(method):
    """`gmres[:M]`, `bicgstab` or `direct` → (kind, restart)."""
    kind, _, restart = method.partition(":")
    if kind not in ("gmres", "bicgstab", "direct") or (restart and kind != "gmres"):
        raise SystemExit(f"ugo_petsc: unknown method \"{method}\": gmres[:M], bicgstab or direct")
    if restart and not restart.isdigit():
        raise SystemExit(f"ugo_petsc: gmres restart \"{restart}\" is not a count")
    return kind, int(restart) if restart else 30


def _ksp(method, A, tolerance, scale, max_iterations, direct_package):
    kind, restart = parse(method)
    ksp = PETSc.KSP().create(comm=A.getComm())
    ksp.setOptionsPrefix(f"{kind}_")
    ksp.setOperators(A)
    pc = ksp.getPC()
    if kind == "direct":
        ksp.setType("preonly")
        pc.setType("lu")
        pc.setFactorSolverType(direct_package)
    else:
        ksp.setType(KSP_TYPES[kind])
        pc.setType("none")
        ksp.setInitialGuessNonzero(True)
        ksp.setTolerances(rtol=0.0, atol=tolerance * scale, divtol=1e10, max_it=max_iterations)
        ksp.setConvergenceHistory(length=max_iterations + 1, reset=True)
        if kind == "gmres":
            ksp.setGMRESRestart(restart)
            PETSc.Options().setValue(f"{kind}_ksp_gmres_modifiedgramschmidt", True)
    ksp.setFromOptions()
    return ksp


def timed_solve(ksp, A, L0):
    """`ksp` set up and run on `A x = L0` from `x_0 = L0`: `(x, seconds, L0 − A x)`."""
    x = L0.duplicate()
    L0.copy(x)
    start = time.perf_counter()
    ksp.setUp()
    ksp.solve(L0, x)
    seconds = time.perf_counter() - start
    r = L0.duplicate()
    A.mult(x, r)
    r.aypx(-1.0, L0)
    return x, seconds, r


def solve(method, A, L0, tolerance, max_iterations, direct_package):
    """Solves `A x = L0` by `method` (see `parse`); `x_0 = L0` for the iterations."""
    scale = L0.norm()
    ksp = _ksp(method, A, tolerance, scale, max_iterations, direct_package)
    x, seconds, r = timed_solve(ksp, A, L0)
    pc = ksp.getPC()
    solver = f"{ksp.getType()}, pc {pc.getType()}"
    if pc.getType() == "lu":
        solver += f" ({pc.getFactorSolverType()})"
    history = [h / scale for h in ksp.getConvergenceHistory()] if parse(method)[0] != "direct" else []
    return Run(
        method=method,
        x=x,
        iterations=ksp.getIterationNumber(),
        seconds=seconds,
        reason=int(ksp.getConvergedReason()),
        history=history,
        residual=r.norm() / scale,
        solver=solver,
    )

