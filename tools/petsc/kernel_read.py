"""Reading ugo's kernel into distributed PETSc objects (docs/petsc.md).

Two sources, one result (`Kernel`): the `/kernel` group of a solution file written by
`ugo solve CASE --save-kernel` (docs/kernel-file.md), or the PETSc binary files of
`ugo export FILE.h5 --format petsc` (`K.petsc`, `L0.petsc`). The hierarchical kernel
(`/kernel/hierarchy`) is read by hierarchy.py into the same `Kernel`, `K` a product of
factors; it shares `patch_range`, `blocks`, `_mat` and `_vec` from here.

From `/kernel`, every rank reads with h5py only the rows of `G` it needs: the rows of the
patches it owns and of their twins behind two-sided transmitting surfaces, and forms its
rows of `K = B·G` (docs/design.md §3) with scipy:

    K[i·C + k, :] = Σ_d ρ̄_m(i)(k,d) G[i·C + d, :] + Σ_d τ̄_m(i)(k,d) G[twin(i)·C + d, :]

with C the direction cells per patch. Ranks own whole patches, so a patch's C rows never
straddle two ranks. `G`'s own rows are kept as well: the patches' illuminance
`E_i = π Σ_d (G x + D)(i,d)` (src/readout/illuminance.rs) is formed from them.

From the PETSc files (`K.petsc`, `I-K.petsc`, `L0.petsc`), `MatLoad` and `VecLoad`
distribute the rows (PETSc's even split); `G` is not in the export, so there is no
illuminance.
"""

import os
from dataclasses import dataclass

import h5py
import numpy as np
import scipy.sparse as sp
from petsc4py import PETSc

import hyperslabs

NO_TWIN = 0xFFFFFFFF


@dataclass
class Kernel:
    """`K` as a PETSc operator, `L0`, and what the solution file needs."""

    K: PETSc.Mat
    L0: PETSc.Vec
    cells: int
    # The local rows of G and D (None when read from the PETSc export).
    G: PETSc.Mat = None
    D: PETSc.Vec = None
    # `K` in scipy CSR, this rank's rows, all columns (None from the PETSc export):
    # what `I − K` is assembled from without a copy through PETSc.
    local: sp.csr_matrix = None
    first_row: int = 0
    # `I − K` as exported (`I-K.petsc`), when read from the PETSc export.
    one_minus: PETSc.Mat = None
    # `K` as the product `factors[-1] ⋯ factors[0]` of distributed AIJ matrices, when `K`
    # is a shell over them (the hierarchy, hierarchy.py).
    factors: list = None

    def destroy(self):
        """Frees its PETSc objects now (petsc4py 3.18 frees a dropped one only at a
        collective `garbage_cleanup`): by_parts.py reads one kernel per number of parts."""
        for obj in [self.K, self.L0, self.G, self.D, self.one_minus] + (self.factors or []):
            if obj is not None:
                obj.destroy()


def patch_range(patches, comm):
    """The patches [first, last) rank `comm.rank` owns: an even split of whole patches."""
    size, rank = comm.getSize(), comm.getRank()
    base, extra = divmod(patches, size)
    first = rank * base + min(rank, extra)
    return first, first + base + (1 if rank < extra else 0)


def _rows(g, indptr, runs, cells, n):
    """The rows of /kernel/G of the patches in `runs`, stacked in their order, as CSR."""
    parts = []
    for first, last in runs:
        r0, r1 = first * cells, last * cells
        a, b = int(indptr[r0]), int(indptr[r1])
        ptr = indptr[r0 : r1 + 1] - a
        parts.append(sp.csr_matrix((g["data"][a:b].astype(np.float64), g["indices"][a:b], ptr), shape=(r1 - r0, n)))
    return sp.vstack(parts, format="csr") if parts else sp.csr_matrix((0, n))


def _mat(local, n, comm, columns=None):
    """A distributed AIJ matrix from this rank's rows (scipy CSR, n global columns);
    `columns` is this rank's share of the columns, the local length of the vectors it
    multiplies (default: its row count, as for a square matrix split alike)."""
    local.sort_indices()
    rows = local.shape[0]
    m = PETSc.Mat().createAIJ(size=((rows, PETSc.DETERMINE), (rows if columns is None else columns, n)), comm=comm)
    m.setPreallocationCSR((local.indptr.astype(PETSc.IntType), local.indices.astype(PETSc.IntType), local.data))
    m.assemble()
    return m


def _vec(values, n, comm):
    v = PETSc.Vec().createMPI((len(values), n), comm=comm)
    v.setArray(np.ascontiguousarray(values, dtype=np.float64))
    return v


def from_solution(path, comm=PETSc.COMM_WORLD):
    """`K`, `L0`, `G` and `D` from the /kernel group of `path`, distributed by patches."""
    with h5py.File(path, "r") as f:
        if "kernel" not in f:
            raise SystemExit(f"ugo_petsc: {path}: no /kernel group; write one with `ugo solve CASE --save-kernel`")
        k = f["kernel"]
        reflect, transmit = k["B/reflection"][:], k["B/transmission"][:]
        transmits = k["B/transmits"][:]
        material, twin = k["patch_material"][:], k["twin"][:]
        cells = reflect.shape[1]
        n = len(material) * cells
        first, last = patch_range(len(material), comm)
        indptr = k["G/indptr"][:].astype(np.int64)
        own = _rows(k["G"], indptr, [[first, last]], cells, n)
        behind = [int(twin[i]) for i in range(first, last) if twin[i] != NO_TWIN and transmits[material[i]]]
        runs = [(int(a), int(b)) for a, b in hyperslabs.runs(np.unique(np.asarray(behind, dtype=np.int64)))]
        twins = _rows(k["G"], indptr, runs, cells, n)
        where = {}
        offset = 0
        for a, b in runs:
            for p in range(a, b):
                where[p] = offset + (p - a) * cells
            offset += (b - a) * cells
        local = _local_kernel(own, twins, where, reflect, transmit, transmits, material[first:last], twin[first:last])
        rows = slice(first * cells, last * cells)
        l0, arriving = k["L0"][rows], k["direct/arriving"][rows]
    K = _mat(local, n, comm)
    G = _mat(own, n, comm)
    return Kernel(K=K, L0=_vec(l0, n, comm), cells=cells, G=G, D=_vec(arriving, n, comm), local=local, first_row=first * cells)


def _local_kernel(own, twins, where, reflect, transmit, transmits, material, twin):
    """This rank's rows of K = B·G: each patch's block times its rows (and its twin's)."""
    cells = reflect.shape[1]
    extra = own.shape[0]
    stacked = sp.vstack([own, twins], format="csr")
    b = blocks(reflect, transmit, transmits, material, twin, lambda j: j * cells, lambda t: extra + np.array([where[p] for p in t.tolist()], dtype=np.int64), stacked.shape[0])
    return (b @ stacked).tocsr()


def blocks(reflect, transmit, transmits, material, twin, own_column, twin_column, columns):
    """This rank's rows of B (its patches `material`, `twin`), as scipy CSR with `columns`
    columns: patch j's row block `ρ̄_m(j)` at column `own_column(j)` and, behind a two-sided
    transmitting surface, `τ̄_m(j)` at `twin_column(twin[j])` (both of arrays of patches)."""
    cells = reflect.shape[1]
    out, inc = (a.ravel() for a in np.meshgrid(np.arange(cells), np.arange(cells), indexing="ij"))
    own = np.arange(len(material))
    through = own[(twin != NO_TWIN) & (transmits[material] != 0)]
    rows = [own[:, None] * cells + out, through[:, None] * cells + out]
    cols = [own_column(own)[:, None] + inc, twin_column(twin[through].astype(np.int64))[:, None] + inc]
    vals = [reflect[material].reshape(len(own), cells * cells), transmit[material[through]].reshape(len(through), cells * cells)]
    shape = (len(material) * cells, columns)
    return sp.csr_matrix((np.concatenate(vals, axis=None), (np.concatenate(rows, axis=None), np.concatenate(cols, axis=None))), shape=shape)


def from_export(folder, cells, comm=PETSc.COMM_WORLD):
    """`K` and `L0` from `K.petsc` and `L0.petsc` of `ugo export --format petsc`."""
    def load(kind, name):
        path = os.path.join(folder, name)
        if not os.path.exists(path):
            raise SystemExit(f"ugo_petsc: {path}: not found; write it with `ugo export FILE.h5 --format petsc -o {folder}`")
        viewer = PETSc.Viewer().createBinary(path, "r", comm=comm)
        obj = kind().create(comm=comm)
        obj.load(viewer)
        viewer.destroy()
        return obj

    K = load(PETSc.Mat, "K.petsc")
    L0 = load(PETSc.Vec, "L0.petsc")
    return Kernel(K=K, L0=L0, cells=cells, one_minus=load(PETSc.Mat, "I-K.petsc"))
