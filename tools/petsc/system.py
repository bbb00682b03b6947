"""The operator `A = I − K` of `(I − K) L = L0` (docs/design.md §2), in two forms:

* assembled (`assembled`): an AIJ matrix, from this rank's rows of `K` in scipy CSR, or,
  for a `K` given as factors (the hierarchy), their product by PETSc's sparse products;
  what the direct solver (an LU factorization) needs;
* matrix-free (`shell`): a PETSc shell matrix whose product is `y = x − K x`, calling only
  `K.mult`. Krylov solvers (KSP) and SLEPc need nothing else, so any `K` that can be applied
  across the ranks plugs in here: the assembled `K` of the kernel file today (the test
  checks the two forms give the same GMRES history), a shell `K` calling ugo's
  hierarchical apply later (docs/petsc.md).
"""

import scipy.sparse as sp
from petsc4py import PETSc


class OneMinus:
    """The shell context of `I − K`: `mult(x) = x − K x`, `multTranspose` likewise."""

    def __init__(self, K):
        self.K = K
        self.work = K.createVecLeft()

    def mult(self, mat, x, y):
        self.K.mult(x, self.work)
        x.copy(y)
        y.axpy(-1.0, self.work)

    def destroy(self, mat):
        """Frees the work vector with the shell (petsc4py calls it); `K` is its owner's."""
        self.work.destroy()

    def multTranspose(self, mat, x, y):
        self.K.multTranspose(x, self.work)
        x.copy(y)
        y.axpy(-1.0, self.work)


def shell(K):
    """`I − K` as a shell matrix over any operator `K` with `mult` (and `multTranspose`)."""
    A = PETSc.Mat().createPython(K.getSizes(), OneMinus(K), comm=K.getComm())
    A.setUp()
    return A


def assembled(kernel):
    """`I − K` as an AIJ matrix with `K`'s row layout (needs the kernel's CSR rows)."""
    if kernel.one_minus is not None:
        return kernel.one_minus
    if kernel.factors is not None:
        return _multiplied_out(kernel.factors)
    local = kernel.local
    rows, n = local.shape[0], local.shape[1]
    eye = sp.eye(rows, n, k=kernel.first_row, format="csr")
    a = (eye - local).tocsr()
    a.sort_indices()
    A = PETSc.Mat().createAIJ(size=((rows, n), (rows, n)), comm=kernel.K.getComm())
    A.setPreallocationCSR((a.indptr.astype(PETSc.IntType), a.indices.astype(PETSc.IntType), a.data))
    A.assemble()
    return A


def _multiplied_out(factors):
    """`I − factors[-1] ⋯ factors[0]` as an AIJ matrix (PETSc's distributed MatMatMult)."""
    product = factors[0]
    for f in factors[1:]:
        product = f.matMult(product)
    product.scale(-1.0)
    product.setOption(PETSc.Mat.Option.NEW_NONZERO_ALLOCATION_ERR, False)
    product.shift(1.0)
    return product
