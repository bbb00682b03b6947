"""The spectrum of `K` and the singular values of `I − K` with SLEPc (docs/petsc.md).

* `eigenvalues`: the `count` eigenvalues of largest magnitude of `K` by Krylov–Schur
  (SLEPc's EPS, non-Hermitian), their residuals `‖K v − λ v‖₂/|λ|`, and the eigenvector
  of the largest: `ρ(K)` is its modulus (`docs/design.md` §4; ugo's `norms` finds it by power
  iteration on `K + I`, src/solve/norms.rs). `K ≥ 0`, so the dominant eigenvalue is the
  real Perron root and its eigenvector can be taken non-negative; it is scaled to
  `max |v| = 1` and signed so.
* `singular_values`: the largest and smallest singular values of `I − K` (SLEPc's SVD,
  thick-restart Lanczos), `cond₂(I − K) = σ_max/σ_min`. Both need only products with
  `I − K` and its transpose, so they run on the shell operator as well; the smallest
  converges slowly when `σ_min` is clustered, hence an option of its own.
"""

import time
from dataclasses import dataclass

import numpy as np
from petsc4py import PETSc
from slepc4py import SLEPc


@dataclass
class Spectrum:
    values: np.ndarray
    # ‖K v − λ v‖₂/|λ| of each.
    errors: np.ndarray
    # The dominant eigenvector (a distributed Vec), max |v| = 1, non-negative sum.
    vector: PETSc.Vec
    # Every converged eigenvector's real part, each scaled as `vector` (distributed Vecs).
    vectors: list
    seconds: float


@dataclass
class Singular:
    largest: float
    smallest: float
    seconds: float


def eigenvalues(K, count, tolerance=1e-12):
    """The `count` eigenvalues of `K` of largest magnitude, Krylov–Schur."""
    eps = SLEPc.EPS().create(comm=K.getComm())
    eps.setOperators(K)
    eps.setProblemType(SLEPc.EPS.ProblemType.NHEP)
    eps.setType(SLEPc.EPS.Type.KRYLOVSCHUR)
    eps.setWhichEigenpairs(SLEPc.EPS.Which.LARGEST_MAGNITUDE)
    eps.setDimensions(nev=count)
    eps.setTolerances(tol=tolerance, max_it=10000)
    eps.setOptionsPrefix("spectrum_")
    eps.setFromOptions()
    start = time.perf_counter()
    eps.solve()
    seconds = time.perf_counter() - start
    found = min(eps.getConverged(), count)
    if found == 0:
        raise SystemExit("ugo_petsc: SLEPc found no eigenvalue of K (raise -spectrum_eps_max_it?)")
    values, errors, vectors = [], [], []
    vr, vi = K.createVecRight(), K.createVecRight()
    for j in range(found):
        values.append(eps.getEigenpair(j, vr, vi))
        errors.append(eps.computeError(j, SLEPc.EPS.ErrorType.RELATIVE))
        v = vr.copy()
        peak = v.max()[1], v.min()[1]
        v.scale(1.0 / (peak[0] if abs(peak[0]) >= abs(peak[1]) else peak[1]))
        vectors.append(v)
    return Spectrum(np.array(values), np.array(errors), vectors[0], vectors, seconds)


def singular_values(A, smallest=True, tolerance=1e-10):
    """σ_max and (with `smallest`) σ_min of `A = I − K`; NaN for one not computed."""
    def extreme(which):
        svd = SLEPc.SVD().create(comm=A.getComm())
        svd.setOperators(A)
        svd.setType(SLEPc.SVD.Type.TRLANCZOS)
        svd.setWhichSingularTriplets(which)
        svd.setDimensions(nsv=1)
        svd.setTolerances(tol=tolerance, max_it=100000)
        svd.setOptionsPrefix("singular_")
        svd.setFromOptions()
        svd.solve()
        return svd.getValue(0) if svd.getConverged() > 0 else float("nan")

    start = time.perf_counter()
    largest = extreme(SLEPc.SVD.Which.LARGEST)
    low = extreme(SLEPc.SVD.Which.SMALLEST) if smallest else float("nan")
    return Singular(largest, low, time.perf_counter() - start)
