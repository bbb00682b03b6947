"""The diagonal blocks of the hierarchical kernel by part (issue 36, point 4; docs/petsc.md,
"Block Jacobi by part"): for part `p`, whose leaves are the contiguous run `[a, b)`,

    K_pp = B_pp · diag(receive_p) · P_p · Λ_p · R_p · diag(send_p)

the chain of hierarchy.py restricted to the part's rows and columns, never multiplied out:

* `R_p`, the pull's columns of the part's leaves, and only the nodes above them (the
  part's elements and the clusters over its roots, some of which span other parts);
* `P_p`, the push's rows of the part's leaves, and only the bundles they take light from;
* `Λ_p`, the links of those bundles from those nodes: a link whose source holds no leaf
  of the part contributes nothing to the block (it is `K`'s off-diagonal part);
* `B_pp`, the material blocks of the part's leaves: their reflection, and the
  transmission from their twins behind two-sided transmitting surfaces, whose light the
  push brings to them as to the part's leaves even when the twin lies in another part
  (`K_pp = Σ_q B_pq G_qp`).

Each factor is a sequential AIJ matrix (`COMM_SELF`) on the rank that owns the part, so a
block's product needs no communication. A rank reads only what its parts' blocks need, by
HDF5 hyperslabs (hyperslabs.py): the tree whole (O(T), to walk up from the part's leaves),
the push rows of `lit` (the part's leaves and their transmitting twins), the gather rows
of the bundles those rows take, the `send`, `receive`, materials and twins of those
leaves; never another part's rows of the links or the push. Reading the parts' own links
from part files is the second round that is not built.
"""

from dataclasses import dataclass

import h5py
import numpy as np
import scipy.sparse as sp
from petsc4py import PETSc

import system
from hierarchy import LINK_FIELDS, PUSH_FIELDS, ancestry, chain, links, positions_in, pull, pushed, read_tree
from hyperslabs import Csr, Record, at, span
from kernel_read import NO_TWIN, _mat, blocks


@dataclass
class Block:
    """Part `part`'s leaves `[first, last)`, its `K_pp` (a shell over sequential factors)
    and `I − K_pp`."""

    part: int
    first: int
    last: int
    K: PETSc.Mat
    A: PETSc.Mat

    def destroy(self):
        """Frees its PETSc objects now (as `kernel_read.Kernel.destroy`)."""
        for obj in [self.A, self.K] + self.K.getPythonContext().factors:
            obj.destroy()


def part_blocks(path, bounds, mine, record=None):
    """The blocks of the parts `mine` (consecutive), part `p` holding the leaves
    `bounds[p]` to `bounds[p + 1]`, from the hierarchy of `path`, reading only what they
    need (hyperslabs.py; what was read is added to `record`)."""
    record = record or Record()
    first, last = int(bounds[mine[0]]), int(bounds[mine[-1] + 1])
    with h5py.File(path, "r") as f:
        k = f["kernel"]
        h = k["hierarchy/operator"]
        share = f["directions/projected"][:] / np.pi
        tree = read_tree(h, record)
        gather, push = Csr(h, "gather", record), Csr(h, "push", record)
        material, twin = span(k["patch_material"], first, last, record), span(k["twin"], first, last, record)
        reflect, transmit, transmits = k["B/reflection"][:], k["B/transmission"][:], k["B/transmits"][:]
        out = []
        for p in mine:
            a, b = int(bounds[p]), int(bounds[p + 1])
            own = slice(a - first, b - first)
            lit = _lit(a, b, material[own], twin[own], transmits)
            factors = _factors(h, tree, gather, push, share, (a, b), lit, record)
            column = {int(t): i for i, t in enumerate(lit)}
            cells = len(share)
            B = blocks(reflect, transmit, transmits, material[own], twin[own], lambda j: j * cells, lambda t: np.array([column[p] for p in t.tolist()], dtype=np.int64) * cells, len(lit) * cells)
            K = chain(factors + [_seq(B)])
            out.append(Block(part=p, first=a, last=b, K=K, A=system.shell(K)))
    return out


def _factors(h, tree, gather, push, share, leaves, lit, record):
    """`R_p`, `Λ_p`, `P_p` (sequential, `diag(send)` and `diag(receive)` folded in) of the
    part of the leaves `leaves` (first, last), whose gathered light `B` gives them from
    `lit`: the push rows of `lit`, the gather rows of the bundles they take, and the pull
    of the nodes above the part's leaves, each read alone."""
    cells = len(share)
    a, b = leaves
    found = ancestry(tree, np.arange(a, b))
    nodes = np.unique(found[1])
    R = pull(tree, share, found, nodes, a, b - a, span(h["send"], a, b, record))
    above = np.flatnonzero(R.getnnz(axis=1))
    row, values = push.rows(lit, PUSH_FIELDS)
    taken = np.unique(values["bundle"]).astype(np.int64)
    receive = at(h["receive"], lit, record)
    P = sp.diags(np.repeat(receive, cells)) @ pushed(row, {**values, "bundle": np.searchsorted(taken, values["bundle"])}, cells, len(lit), len(taken))
    Lam = links(*_reaching(gather, taken, nodes), share, len(taken), len(nodes))
    return [_seq(R[above]), _seq(Lam[:, above]), _seq(P)]


def _reaching(gather, taken, nodes):
    """Of the links of the bundles `taken` (their gather rows), those whose source is one of
    `nodes` (sorted): the others read no leaf of the part. Their rows (indices in `taken`)
    and entries, the sources as indices in `nodes`."""
    row, values = gather.rows(taken, LINK_FIELDS)
    source, reached = positions_in(nodes, values["source"])
    return row[reached], {name: v[reached] for name, v in values.items()} | {"source": source[reached]}


def _lit(a, b, material, twin, transmits):
    """The leaves whose gathered light `B` gives the leaves `[a, b)` (their `material` and
    `twin`): themselves, then the twins outside `[a, b)` that transmit to them."""
    mine = np.arange(a, b)
    behind = twin[(twin != NO_TWIN) & (transmits[material] != 0)].astype(np.int64)
    outside = np.unique(behind[(behind < a) | (behind >= b)])
    return np.concatenate([mine, outside])


def _seq(m):
    """A scipy matrix as a sequential AIJ matrix."""
    m = sp.csr_matrix(m)
    return _mat(m, m.shape[1], PETSc.COMM_SELF, columns=m.shape[1])
