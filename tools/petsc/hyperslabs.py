"""What a rank reads of a saved hierarchy: rows of `/kernel/hierarchy/operator`'s CSR
arrays by HDF5 hyperslabs, and the record of what was read (docs/petsc.md, "What each
rank reads").

`operator/gather` (by bundle) and `operator/push` (by leaf) are CSR: `indptr` (rows + 1)
and entry arrays. `Csr` reads `indptr` whole (8 bytes a row) and, of the entry
arrays, only the runs of entries of the rows asked for: an h5py slice `ds[s:e]` selects a
hyperslab, so HDF5 reads those entries alone. `span` reads a run of a per-row array
(`receive`, `L0`, …) the same way, `at` some rows of one run by run, and `whole` an
array every rank needs whole (the tree).

Every read of the operator and of the per-leaf arrays goes through a `Record` (the
material blocks, the directions and parts.py's root positions, a few kB, do not): the
bytes read, and the distinct rows of each CSR, which the report gives per rank with its
peak resident memory (`per_rank`, `peak_resident`; `--report`: `parts[i].read`) and
check_parts.py compares with the rows the rank's parts and factors need.
"""

import numpy as np


class Record:
    """The bytes read, and the rows read of each CSR (`gather`, `push`), distinct."""

    def __init__(self):
        self.bytes = 0
        self.rows = {}

    def add(self, name, ids):
        self.rows[name] = np.union1d(self.rows.get(name, np.empty(0, np.int64)), ids)

    def summary(self):
        """`[bytes, distinct gather rows, distinct push rows]`, the per-rank figures."""
        return [self.bytes] + [len(self.rows.get(name, ())) for name in ("gather", "push")]


def whole(dataset, record):
    """All of `dataset`."""
    values = dataset[...]
    record.bytes += values.nbytes
    return values


def span(dataset, first, last, record):
    """Elements `[first, last)` of `dataset` (one hyperslab)."""
    values = dataset[first:last]
    record.bytes += values.nbytes
    return values


def at(dataset, ids, record):
    """`dataset[ids]` for distinct `ids` in any order, read run by run of consecutive ids."""
    ids = np.asarray(ids, dtype=np.int64)
    order = np.argsort(ids, kind="stable")
    pieces = [span(dataset, int(s), int(e), record) for s, e in runs(ids[order])]
    values = np.empty(len(ids), dtype=dataset.dtype)
    values[order] = np.concatenate(pieces) if pieces else values
    return values


def runs(ids):
    """Sorted distinct ids as `(first, last)` runs of consecutive ids."""
    if len(ids) == 0:
        return np.empty((0, 2), np.int64)
    breaks = np.flatnonzero(np.diff(ids) != 1) + 1
    return np.stack([ids[np.r_[0, breaks]], ids[np.r_[breaks - 1, len(ids) - 1]] + 1], axis=1)


class Csr:
    """A CSR of `/kernel/hierarchy/operator` (`gather`, `push`): its `indptr`, read whole
    (8 bytes a row), and `rows`, the entries of some rows read by hyperslabs."""

    def __init__(self, group, name, record):
        self.csr, self.name, self.record = group[name], name, record
        self.indptr = whole(self.csr["indptr"], record).astype(np.int64)
        self.count = len(self.indptr) - 1

    def rows(self, ids, fields):
        """Rows `ids` (distinct, any order): `(row, values)`, `row[e]` the index in `ids`
        of entry `e`'s row, `values[field]` the entries of `fields`, read run by run of
        consecutive rows straight into their place."""
        ids = np.asarray(ids, dtype=np.int64)
        order = np.argsort(ids, kind="stable")
        ordered = ids[order]
        self.record.add(self.name, ordered)
        sizes = self.indptr[ordered + 1] - self.indptr[ordered]
        values = {field: np.empty(int(sizes.sum()), dtype=self.csr[field].dtype) for field in fields}
        at = 0
        for first, last in runs(ordered):
            s, e = int(self.indptr[first]), int(self.indptr[last])
            for field in fields if e > s else ():
                self.csr[field].read_direct(values[field], np.s_[s:e], np.s_[at : at + e - s])
                self.record.bytes += (e - s) * values[field].itemsize
            at += e - s
        return np.repeat(order, sizes), values


def per_rank(values, comm):
    """Each rank's `values` (numbers, as many on every rank), as one list per rank on rank
    0 (None elsewhere)."""
    from petsc4py import PETSc

    import solution_file

    mine = PETSc.Vec().createMPI((len(values), PETSc.DECIDE), comm=comm)
    mine.setArray(np.asarray(values, dtype=np.float64))
    every = solution_file.gather(mine)
    return None if every is None else every.reshape(comm.getSize(), len(values)).tolist()


def peak_resident():
    """This process's peak resident memory so far, bytes (`ru_maxrss`, KiB on Linux)."""
    import resource

    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024
