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
block's product needs no communication. Every rank reads the pull, links and push of the
whole file (scipy, from `/kernel/hierarchy/operator`) and keeps its parts' pieces; reading
the parts' own links from part files is the second round that is not built.
"""

from dataclasses import dataclass

import h5py
import numpy as np
import scipy.sparse as sp
from petsc4py import PETSc

import system
from hierarchy import _links, _pull, _push, chain
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


def part_blocks(path, bounds, mine):
    """The blocks of the parts `mine`, part `p` holding the leaves `bounds[p]` to
    `bounds[p + 1]`, from the hierarchy of `path`."""
    with h5py.File(path, "r") as f:
        k = f["kernel"]
        h = k["hierarchy/operator"]
        share = f["directions/projected"][:] / np.pi
        cells, leaves = len(share), len(k["patch_material"])
        nodes, bundles = len(h["parent"]), len(h["gather/indptr"]) - 1
        pull = _pull(h, share, (0, nodes)).tocsc()
        links = _links(h, share, (0, bundles), nodes)
        push = _push(h, cells, (0, leaves), bundles)
        send, receive = np.repeat(h["send"][:], cells), np.repeat(h["receive"][:], cells)
        material, twin = k["patch_material"][:], k["twin"][:]
        reflect, transmit, transmits = k["B/reflection"][:], k["B/transmission"][:], k["B/transmits"][:]
        out = []
        for p in mine:
            a, b = int(bounds[p]), int(bounds[p + 1])
            cols = slice(a * cells, b * cells)
            R = (pull[:, cols] @ sp.diags(send[cols])).tocsr()
            above = np.flatnonzero(R.getnnz(axis=1))
            lit = _lit(a, b, material, twin, transmits)
            rows = (lit[:, None] * cells + np.arange(cells)).ravel()
            P = (sp.diags(receive[rows]) @ push[rows]).tocsc()
            taken = np.flatnonzero(P.getnnz(axis=0))
            Lam = links[taken][:, above]
            at = {int(t): i for i, t in enumerate(lit)}
            B = blocks(reflect, transmit, transmits, material[a:b], twin[a:b], lambda j: j * cells, lambda t: at[t] * cells, len(lit) * cells)
            factors = [_seq(R[above]), _seq(Lam), _seq(P[:, taken]), _seq(B)]
            K = chain(factors)
            out.append(Block(part=p, first=a, last=b, K=K, A=system.shell(K)))
    return out


def _lit(a, b, material, twin, transmits):
    """The leaves whose gathered light `B` gives the leaves `[a, b)`: themselves, then the
    twins outside `[a, b)` that transmit to them."""
    mine = np.arange(a, b)
    t, m = twin[a:b], material[a:b]
    behind = t[(t != NO_TWIN) & (transmits[m] != 0)].astype(np.int64)
    outside = np.unique(behind[(behind < a) | (behind >= b)])
    return np.concatenate([mine, outside])


def _seq(m):
    """A scipy matrix as a sequential AIJ matrix."""
    m = sp.csr_matrix(m)
    return _mat(m, m.shape[1], PETSc.COMM_SELF, columns=m.shape[1])
