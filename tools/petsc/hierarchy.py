"""The hierarchical kernel of a solution file (`/kernel/hierarchy`, docs/kernel-file.md)
as distributed PETSc factors, never multiplied out for the Krylov solvers (docs/petsc.md):

    K = B · diag(receive) · P · Λ · R · diag(send)

with, every leaf and bundle index times the C cells plus the cell, every node index times
S = max(C, 6) plus its value (N leaves, T tree nodes by depth-first position, U bundles):

* `R` (TS × NC), the pull: an element ← the area-weighted mean of the leaves under it (the
  product of the area shares on the way up), in its C cells; a cluster's six values, each
  the cell-weighted mean `Σ_m (μ_m/π) x_m` over its elements' exposed area facing one axis
  direction (`+x, −x, +y, −y, +z, −z`: the product of the facing shares from the way
  into the clusters up);
* `Λ` (UC × TS), the links: bundle `(b, d)` ← node `(q, m)` by `F^{d,m}`, `d = 65535`
  spread over the cells as `μ_d/π` (for a cluster source, `m` names a facing value);
* `P` (NC × UC), the push: leaf `(l, d)` ← bundle `(b, d)` by the leaf's share;
* `B` (NC × NC), the material blocks (kernel_read.blocks), as for the explicit kernel.

The diagonals are folded in: `receive` scales `P`'s rows, `send` `R`'s columns. Each
factor is an AIJ matrix whose rows are split over the ranks and whose column split is the
row split of the factor applied before it, so the chain multiplies without redistribution:
leaves by whole leaves (`kernel_read.patch_range`, as patches), nodes and bundles evenly.
Every rank reads the tree whole (parents, weights, facing shares, clusters, the leaves'
positions: O(T))
and, by hyperslabs (hyperslabs.py), only its own rows of the links' pieces, of the push and
of the per-leaf vectors, and the `send` of the leaves its rows of the pull reach.

`K` and `G = diag(receive)·P·Λ·R·diag(send)` (for the illuminance) are shell matrices
applying the chain (`Chain`), with the transpose for SLEPc's SVD. `direct` needs `K` on the
leaves: `check_expansion` refuses it, naming the figures, when an upper bound on its
non-zeros does not fit the memory limit; `system.assembled` then multiplies the factors.
"""

from dataclasses import dataclass

import h5py
import numpy as np
import scipy.sparse as sp
from petsc4py import PETSc

from hyperslabs import Csr, Record, span, whole
from kernel_read import NO_TWIN, Kernel, _mat, _vec, blocks, patch_range

# `gather/d` of a link whose light arrives in all cells alike (`link.rs`'s ALL_CELLS).
ALL_CELLS = 65535
# The values of a cluster: its light by the axis direction its elements face (`node.rs`'s FACING).
FACING = 6
# AIJ bytes per stored non-zero: an f64 value and an int32 column index.
BYTES_PER_NONZERO = 12


def is_hierarchical(path):
    """Whether the solution file's `/kernel` holds the hierarchy (attribute `kernel`)."""
    with h5py.File(path, "r") as f:
        return "kernel" in f and f["kernel"].attrs.get("kernel") == "hierarchical"


class Chain:
    """The shell context of a product of matrices, `factors[-1] ⋯ factors[0]`: `mult`
    applies them first to last, `multTranspose` their transposes last to first."""

    def __init__(self, factors):
        self.factors = factors
        self.between = [f.createVecLeft() for f in factors[:-1]]

    def mult(self, mat, x, y):
        for f, out in zip(self.factors, self.between + [y]):
            f.mult(x, out)
            x = out

    def destroy(self, mat):
        """Frees the vectors between the factors with the shell (petsc4py calls it); the
        factors are their owner's."""
        for v in self.between:
            v.destroy()

    def multTranspose(self, mat, x, y):
        ins = [x] + self.between[::-1]
        outs = self.between[::-1] + [y]
        for f, a, b in zip(self.factors[::-1], ins, outs):
            f.multTranspose(a, b)


def chain(factors):
    """`factors[-1] ⋯ factors[0]` as a shell matrix."""
    sizes = (factors[-1].getSizes()[0], factors[0].getSizes()[1])
    m = PETSc.Mat().createPython(sizes, Chain(factors), comm=factors[0].getComm())
    m.setUp()
    return m


def from_solution(path, comm=PETSc.COMM_WORLD, leaf_rows=None, record=None):
    """`K = B·G` and `G` as chains of distributed factors, `L0` and `D`, from `path`; this
    rank owns the leaves `leaf_rows` (first, last), by default an even split, and reads
    only its rows of each factor (hyperslabs.py; what it read is added to `record`)."""
    record = record or Record()
    with h5py.File(path, "r") as f:
        k = f["kernel"]
        if "hierarchy/operator" not in k:
            raise SystemExit(f"ugo_petsc: {path}: /kernel says kernel = \"hierarchical\" but has no /kernel/hierarchy/operator; save it again with `ugo solve CASE --save-kernel`")
        share = f["directions/projected"][:] / np.pi
        h = k["hierarchy/operator"]
        tree = read_tree(h, record)
        gather, push = Csr(h, "gather", record), Csr(h, "push", record)
        cells, leaves, nodes = len(share), len(tree.leaf_position), len(tree.parent)
        if k["B/reflection"].shape[1] != cells or len(k["patch_material"]) != leaves:
            raise SystemExit(f"ugo_petsc: {path}: /kernel/hierarchy has {leaves} leaves and /directions {cells} cells, /kernel {len(k['patch_material'])} patches of {k['B/reflection'].shape[1]} cells")
        first, last = leaf_rows or patch_range(leaves, comm)
        node_rows, bundle_rows = patch_range(nodes, comm), patch_range(gather.count, comm)
        n, own, stride = leaves * cells, (last - first) * cells, values_per_node(cells)
        sizes = [(node_rows[1] - node_rows[0]) * stride, (bundle_rows[1] - bundle_rows[0]) * cells]
        R = _mat(_node_pull(h, tree, share, node_rows, record), n, comm, columns=own)
        row, values = gather.rows(np.arange(*bundle_rows), LINK_FIELDS)
        Lam = _mat(links(row, values, share, bundle_rows[1] - bundle_rows[0], nodes), nodes * stride, comm, columns=sizes[0])
        receive = np.repeat(span(h["receive"], first, last, record), cells)
        row, values = push.rows(np.arange(first, last), PUSH_FIELDS)
        P = _mat(sp.diags(receive) @ pushed(row, values, cells, last - first, gather.count), gather.count * cells, comm, columns=sizes[1])
        material, twin = span(k["patch_material"], first, last, record), span(k["twin"], first, last, record)
        reflect, transmit, transmits = k["B/reflection"][:], k["B/transmission"][:], k["B/transmits"][:]
        B = _mat(blocks(reflect, transmit, transmits, material, twin, lambda j: (first + j) * cells, lambda t: t * cells, n), n, comm)
        l0, arriving = (span(k[name], first * cells, last * cells, record) for name in ("L0", "direct/arriving"))
    factors = [R, Lam, P, B]
    return Kernel(K=chain(factors), L0=_vec(l0, n, comm), cells=cells, G=chain(factors[:3]), D=_vec(arriving, n, comm), factors=factors)


@dataclass
class Tree:
    """The operator's tree by depth-first position (`operator/{parent,weight,facing_share,
    cluster}`) and each leaf's position (`operator/leaf_position`), read whole by every
    rank: O(T)."""

    parent: np.ndarray
    weight: np.ndarray
    facing_share: np.ndarray
    cluster: np.ndarray
    leaf_position: np.ndarray


def values_per_node(cells):
    """S, the values a node holds in `R`'s rows and `Λ`'s columns: an element's cells, a
    cluster's six facing values."""
    return max(cells, FACING)


def read_tree(h, record):
    """The tree of the operator group `h`."""
    if "facing_share" not in h:
        raise SystemExit(f"ugo_petsc: {h.file.filename}: no {h.name}/facing_share: saved by a ugo before clusters sent light by facing (kernel format 1); save it again with `ugo solve CASE --save-kernel`")
    names = ("parent", "weight", "facing_share", "cluster", "leaf_position")
    parent, weight, facing_share, cluster, at = (whole(h[name], record) for name in names)
    return Tree(parent, weight, facing_share, cluster.astype(bool), at.astype(np.int64))


def ancestry(tree, leaves):
    """Every (leaf, node above it or itself, its weight in the node) for the leaves
    `leaves`, as four arrays: under an element, the product of the area shares from the
    leaf up (`omega`); in a cluster, six weights, one per facing value, the products of the
    facing shares from the way into the clusters up (`facing`, n × 6)."""
    leaf = np.asarray(leaves, dtype=np.int64)
    at, omega, facing = tree.leaf_position[leaf], np.ones(len(leaf)), np.zeros((len(leaf), FACING))
    found = [(leaf, at, omega, facing)]
    while len(at):
        up = tree.parent[at] != NO_TWIN
        leaf, omega, facing, at = leaf[up], omega[up], facing[up], at[up]
        parent = tree.parent[at].astype(np.int64)
        into = tree.cluster[parent][:, None]
        facing = np.where(into, np.where(tree.cluster[at][:, None], facing, omega[:, None]) * tree.facing_share[at], 0.0)
        omega, at = omega * tree.weight[at], parent
        found.append((leaf, at, omega, facing))
    return tuple(np.concatenate(a) for a in zip(*found))


def positions_in(ordered, ids):
    """For each of `ids`, its index in the sorted distinct `ordered`, and whether it is
    there at all."""
    index = np.searchsorted(ordered, ids)
    found = index < len(ordered)
    found[found] = ordered[index[found]] == ids[found]
    return index, found


def pull(tree, share, found, node_rows, first, count, send):
    """Rows `node_rows` (sorted node positions) of R·diag(send) over the leaves `[first,
    first + count)` (`send` theirs), from their `ancestry`: an element ← each leaf under it
    by the product of the area shares, cell by cell; a cluster's facing value `c` ← every
    cell of each leaf by its weight `c` times `μ_m/π`. The leaves that send nothing
    (`send = 0`) are left out."""
    leaf, at, omega, facing = found
    cells, stride = len(share), values_per_node(len(share))
    index, mine = positions_in(node_rows, at)
    leaf, row, omega, facing, spread = leaf[mine] - first, index[mine], omega[mine], facing[mine], tree.cluster[at[mine]]
    cell, value = np.arange(cells), np.arange(FACING)
    e, c = ~spread, spread
    shape = (c.sum(), FACING, cells)
    rows = np.concatenate([
        (row[e, None] * stride + cell).ravel(),
        np.broadcast_to(row[c, None, None] * stride + value[None, :, None], shape).ravel(),
    ])
    cols = np.concatenate([
        (leaf[e, None] * cells + cell).ravel(),
        np.broadcast_to(leaf[c, None, None] * cells + cell[None, None, :], shape).ravel(),
    ])
    vals = np.concatenate([
        np.broadcast_to((omega[e] * send[leaf[e]])[:, None], (e.sum(), cells)).ravel(),
        (facing[c, :, None] * share[None, None, :] * send[leaf[c], None, None]).ravel(),
    ])
    R = sp.csr_matrix((vals, (rows, cols)), shape=(len(node_rows) * stride, count * cells))
    R.eliminate_zeros()
    return R


def _node_pull(h, tree, share, node_rows, record):
    """This rank's rows `node_rows` of R with `diag(send)` folded in (`node_pull`), `send`
    read from the operator group `h`."""
    return node_pull(tree, share, node_rows, lambda start, end: span(h["send"], start, end, record))


def node_pull(tree, share, node_rows, send):
    """This rank's rows `node_rows` (first, last) of R with `diag(send)` folded in, over all
    the leaves: a node precedes its subtree, so only the leaves at or after the first
    node's position can lie under the rank's nodes; only theirs are walked up and only
    their run of the sending factors, `send(first, end)`, is asked for."""
    a, b = node_rows
    cells, leaves = len(share), len(tree.leaf_position)
    walked = np.flatnonzero(tree.leaf_position >= a)
    start = int(walked[0]) if len(walked) else leaves
    tail = pull(tree, share, ancestry(tree, walked), np.arange(a, b), start, leaves - start, send(start, leaves))
    return sp.csr_matrix((tail.data, tail.indices + start * cells, tail.indptr), shape=(tail.shape[0], leaves * cells))


# The entries of a gather row (a bundle's links) and of a push row (a leaf's shares).
LINK_FIELDS = ("source", "d", "m", "f")
PUSH_FIELDS = ("bundle", "share")


def links(row, values, share, count, nodes):
    """`count` rows of Λ, from the gather entries `values` of rows `row` (`Csr.rows`):
    bundle `(b, d)` ← node value `(q, m)` by `f`; `d = ALL_CELLS` spreads `f` over the bundle's
    cells as `μ_d/π` (its cell 0 in place, the other cells after). Built in PETSc's index
    type, in place where it can: this is the largest factor, and its temporaries set the
    peak memory of a rank."""
    cells = len(share)
    d, f = values["d"], values["f"]
    spread = d == ALL_CELLS
    col = values["source"].astype(PETSc.IntType)
    col *= values_per_node(cells)
    col += values["m"]
    rows = row.astype(PETSc.IntType)
    rows *= cells
    rows += np.where(spread, 0, d)
    vals = f.copy()
    vals[spread] *= share[0]
    if cells > 1 and spread.any():
        rows = np.concatenate([rows] + [(row[spread] * cells + c).astype(PETSc.IntType) for c in range(1, cells)])
        col = np.concatenate([col] + [col[spread]] * (cells - 1))
        vals = np.concatenate([vals] + [f[spread] * share[c] for c in range(1, cells)])
    return sp.csr_matrix((vals, (rows, col)), shape=(count * cells, nodes * values_per_node(cells)))


def pushed(row, values, cells, count, bundles):
    """`count` rows of P, from the push entries `values` of rows `row` (`Csr.rows`): leaf
    `(l, d)` ← bundle `(b, d)` by the leaf's share."""
    bundle, w = values["bundle"].astype(np.int64), values["share"]
    cell = np.arange(cells)
    rows = (row[:, None] * cells + cell).ravel()
    cols = (bundle[:, None] * cells + cell).ravel()
    return sp.csr_matrix((np.repeat(w, cells), (rows, cols)), shape=(count * cells, bundles * cells))


def expansion_bound(factors):
    """An upper bound on the non-zeros of `factors[-1] ⋯ factors[0]`: row by row, a row of
    `X·Y` has at most the sum of the row counts of `Y` its entries pick, and at most the
    product's columns."""
    columns = factors[0].getSize()[1]
    count = factors[0].createVecRight()
    count.set(1.0)
    for f in factors:
        indptr, indices, values = f.getValuesCSR()
        pattern = PETSc.Mat().createAIJ(size=f.getSizes(), comm=f.getComm())
        pattern.setPreallocationCSR((indptr, indices, np.ones_like(values)))
        pattern.assemble()
        out = pattern.createVecLeft()
        pattern.mult(count, out)
        out.getArray()[:] = np.minimum(out.getArray(), columns)
        count, _ = out, pattern.destroy()
    return count.sum()


def memory_limit():
    """Half the least of the machine's memory (`MemTotal` of /proc/meminfo) and its control
    group's limit (cgroup v2 `memory.max`, v1 `memory.limit_in_bytes`), bytes, as ugo's
    default (src/kernel/memory.rs; ugo also weighs `ulimit -v`)."""
    with open("/proc/meminfo") as fh:
        least = next(int(line.split()[1]) for line in fh if line.startswith("MemTotal:")) * 1024
    for path in ("/sys/fs/cgroup/memory.max", "/sys/fs/cgroup/memory/memory.limit_in_bytes"):
        try:
            with open(path) as fh:
                least = min(least, int(fh.read().strip()))
            break
        except (OSError, ValueError):
            continue
    return least // 2


def check_expansion(kernel, path, limit):
    """Refuses `direct` when `G`, `K` and `I − K` on the leaves, at the bounds on their
    non-zeros, would not fit `limit` bytes (all ranks together; rank 0 says why); else the
    bound of `K`'s."""
    n = kernel.K.getSize()[0]
    bound = expansion_bound(kernel.factors)
    need = BYTES_PER_NONZERO * (expansion_bound(kernel.factors[:3]) + 2 * bound + n)
    if need > limit:
        raise SystemExit(1 if kernel.K.getComm().getRank() else
            f"ugo_petsc: {path}: direct needs the hierarchical K multiplied out on its {n // kernel.cells:,} leaves × "
            f"{kernel.cells} cells: up to {bound:,.0f} non-zeros of K, {need / 2**30:.2f} GiB for G, K and I − K "
            f"({BYTES_PER_NONZERO} bytes a non-zero), beyond the memory limit of {limit / 2**30:.2f} GiB "
            f"(--memory-limit); gmres and bicgstab apply the factors without it"
        )
    return bound
