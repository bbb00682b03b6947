"""The leaves' parts of a saved hierarchy (issue 36, point 4; docs/petsc.md, "Block Jacobi
by part"), and how whole parts are spread over the ranks.

ugo's partition (src/kernel/hierarchy/partition.rs) puts part `i` of `n` on the roots
whose position in the cluster tree's depth-first order lies in the `i`-th of `n` equal
runs, and every element in its root's part. A saved hierarchy stores each leaf's root's
position (`/kernel/hierarchy/leaves/root_position`, docs/kernel-file.md) and the number of
roots (the attribute `roots`), so a leaf's part of any `n` is `partition.rs`'s `part_of`,
`⌊position · n / roots⌋` (tests/cli/parts.rs checks it against `ugo solve --part i/n`).

The unknowns are the leaves in the tree's depth-first order, so their roots' positions
never decrease along them and each part's leaves are already one contiguous run; that is
checked, not assumed. With `P` ranks and `n` parts (`n` a multiple of `P`), rank `r` owns
the parts `r·n/P` to `(r+1)·n/P − 1`, hence whole parts and a contiguous run of leaves.
"""

import h5py
import numpy as np

ROOT_POSITION = "kernel/hierarchy/leaves/root_position"


def leaf_parts(path, count):
    """Each leaf's part of `count` (the order of the unknowns), refusing a file without
    the roots' positions or whose parts are not contiguous runs of leaves."""
    with h5py.File(path, "r") as f:
        if ROOT_POSITION not in f:
            raise SystemExit(f"ugo_petsc: {path}: no /{ROOT_POSITION} (each leaf's root's position, which decides its part; "
                             "files saved before it lack it): save the hierarchy again with `ugo solve CASE --save-kernel`")
        position = f[ROOT_POSITION][:].astype(np.int64)
        roots = int(f["kernel/hierarchy"].attrs["roots"])
    if len(position) and (position.min() < 0 or position.max() >= roots):
        raise SystemExit(f"ugo_petsc: {path}: /{ROOT_POSITION} holds positions beyond the file's {roots} roots")
    part = position * count // roots
    if np.any(np.diff(part) < 0):
        raise SystemExit(f"ugo_petsc: {path}: /{ROOT_POSITION} does not run through the roots in order, so a part's leaves are not contiguous")
    return part


def bounds(part, count):
    """The first leaf of every part and the end: part `p` is leaves `[b[p], b[p+1])`."""
    return np.searchsorted(part, np.arange(count + 1), side="left")


def parts_of_rank(count, comm):
    """The parts this rank owns (whole parts, an equal number per rank)."""
    size, rank = comm.getSize(), comm.getRank()
    if count < 1 or count % size:
        raise SystemExit(1 if rank else f"ugo_petsc: --parts {count} on {size} ranks: the parts must be a positive multiple of the ranks, so every rank owns whole parts")
    each = count // size
    return range(rank * each, (rank + 1) * each)
