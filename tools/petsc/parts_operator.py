"""The hierarchy's factors from its parts' rows files (from_parts.py; docs/petsc.md, "The
operator from the part files"): each rank reads the rows files of its parts and builds its
rows of `R`, `Λ`, `P`, `B`, `L0` as hierarchy.py does from a saved hierarchy, then
balances `G = P Λ R` to the leaves' closures by ugo's sweeps (src/kernel/hierarchy/
balance.rs and balanced.rs, `closure_targets`), the rules read from the files.
"""

from dataclasses import dataclass

import h5py
import numpy as np
from petsc4py import PETSc

import hierarchy
from kernel_read import _mat, _vec, blocks

# The rows files' `format` this program reads (ROWS_FORMAT in src/io/part_rows_file.rs):
# 3 since a link between elements whose receiver is not a leaf is a bundle of its own,
# keyed by its source's position as well; 4 since a cluster holds six facing values
# (`tree/facing_share`).
ROWS_FORMAT = 4


def bundle_keys(g):
    """The keys of bundles (or of push entries) in group `g`, ordered as the bundles are:
    receiver's position, sources' class (`SourceClass::code` in
    src/kernel/hierarchy/bundle.rs, a u8) and lone source's position (4294967295 for a
    class of sources), in 24, 8 and 32 bits of one u64."""
    receiver, kind, source = (g[name][:].astype(np.uint64) for name in ("receiver", "kind", "source"))
    if len(receiver) and int(receiver.max()) >= 1 << 24:
        raise SystemExit("from_parts: more than 2^24 tree nodes: the bundles' keys do not fit in 64 bits")
    return (receiver << np.uint64(40)) | (kind << np.uint64(32)) | source


@dataclass
class Part:
    """A rows file's place: its part, runs of leaves and nodes, and its bundles' keys."""

    path: str
    index: int
    count: int
    leaves: tuple
    nodes: tuple
    keys: np.ndarray
    fingerprint: dict


def survey(paths):
    """Every rows file's `Part`, in part order; refused unless they are every part of one
    partition of one case."""
    parts = []
    for path in paths:
        try:
            f = h5py.File(path, "r")
        except OSError as e:
            raise SystemExit(f"from_parts: {path}: {e}")
        with f:
            if "rows" not in f:
                raise SystemExit(f"from_parts: {path}: no /rows group (ugo solve CASE --part i/n --linked … writes one)")
            g = f["rows"]
            if int(g.attrs.get("format", 0)) != ROWS_FORMAT:
                raise SystemExit(f"from_parts: {path}: rows format {int(g.attrs.get('format', 0))}, this program reads {ROWS_FORMAT}: form the parts again with this ugo")
            keys = bundle_keys(g["bundles"])
            fingerprint = {k: str(v) for k, v in g["fingerprint"].attrs.items()}
            parts.append(Part(path, int(g.attrs["part"]), int(g.attrs["parts"]), tuple(int(v) for v in g.attrs["leaves"]), tuple(int(v) for v in g.attrs["nodes"]), keys, fingerprint))
    parts.sort(key=lambda p: p.index)
    for p in parts:
        if p.fingerprint != parts[0].fingerprint:
            raise SystemExit(f"from_parts: {p.path} and {parts[0].path} were formed for different cases")
    count = parts[0].count
    if [p.index for p in parts] != list(range(count)) or any(p.count != count for p in parts):
        raise SystemExit(f"from_parts: the files are parts {[f'{p.index}/{p.count}' for p in parts]}: give every part of one partition once")
    for a, b in zip(parts, parts[1:]):
        if a.leaves[1] != b.leaves[0] or a.nodes[1] != b.nodes[0]:
            raise SystemExit(f"from_parts: {a.path} and {b.path}: their leaves or nodes do not follow on")
    keys = np.concatenate([p.keys for p in parts])
    if np.any(np.diff(keys) <= 0):
        raise SystemExit("from_parts: the parts' bundles are not in the one-process order: parts of different linkings?")
    return parts, keys


def concatenated(files, name, dtype=None):
    """`/rows/name` of the open `files`, one after another."""
    arrays = [f["rows"][name][:] for f in files]
    return np.concatenate(arrays).astype(dtype) if dtype else np.concatenate(arrays)


def csr(files, group, fields):
    """The CSR `group` of `files` stacked: its row of every entry, and the entries' fields."""
    counts = [np.diff(f["rows"][group]["indptr"][:].astype(np.int64)) for f in files]
    counts = np.concatenate(counts)
    row = np.repeat(np.arange(len(counts)), counts)
    return row, {name: concatenated(files, f"{group}/{name}") for name in fields}


class Operator:
    """A rank's factors of `K = B·diag(receive)·P·Λ·R·diag(send)`, unbalanced until `balance`."""

    def __init__(self, paths, comm):
        parts, keys = survey(paths)
        ranks, rank = comm.getSize(), comm.getRank()
        if len(parts) % ranks:
            raise SystemExit(f"from_parts: {len(parts)} parts on {ranks} ranks: the parts must be a multiple of the ranks")
        per = len(parts) // ranks
        mine = parts[rank * per:(rank + 1) * per]
        offsets = np.cumsum([0] + [len(p.keys) for p in parts])
        files = [h5py.File(p.path, "r") for p in mine]
        try:
            self._build(files, mine, keys, int(offsets[rank * per]), int(offsets[(rank + 1) * per]), comm)
        finally:
            for f in files:
                f.close()

    def _build(self, files, mine, keys, b0, b1, comm):
        g = files[0]["rows"]
        share = g["projected"][:] / np.pi
        cells = self.cells = len(share)
        tree = hierarchy.Tree(g["tree/parent"][:], g["tree/weight"][:], g["tree/facing_share"][:], g["tree/cluster"][:].astype(bool), g["tree/leaf_position"][:].astype(np.int64))
        self.leaves, self.nodes, self.bundles = len(tree.leaf_position), len(tree.parent), len(keys)
        first, last = mine[0].leaves[0], mine[-1].leaves[1]
        a, b = mine[0].nodes[0], mine[-1].nodes[1]
        n, own, stride = self.leaves * cells, (last - first) * cells, hierarchy.values_per_node(cells)
        R = _mat(hierarchy.node_pull(tree, share, (a, b), lambda start, end: np.ones(end - start)), n, comm, columns=own)
        row, values = csr(files, "gather", hierarchy.LINK_FIELDS)
        Lam = _mat(hierarchy.links(row, values, share, b1 - b0, self.nodes), self.nodes * stride, comm, columns=(b - a) * stride)
        row, values = csr(files, "push", ("receiver", "kind", "source", "share"))
        wanted = bundle_keys(values)
        bundle = np.searchsorted(keys, wanted)
        if np.any(keys[np.minimum(bundle, len(keys) - 1)] != wanted):
            raise SystemExit("from_parts: a leaf's push names a bundle no part holds: parts of different linkings?")
        P = _mat(hierarchy.pushed(row, {"bundle": bundle, "share": values["share"]}, cells, last - first, self.bundles), self.bundles * cells, comm, columns=(b1 - b0) * cells)
        material, twin = concatenated(files, "material"), concatenated(files, "twin")
        reflect, transmit, transmits = g["B/reflection"][:], g["B/transmission"][:], g["B/transmits"][:]
        B = _mat(blocks(reflect, transmit, transmits, material, twin, lambda j: (first + j) * cells, lambda t: t * cells, n), n, comm)
        self.factors_ = [R, Lam, P, B]
        self.G = hierarchy.chain([R, Lam, P])
        self.K = hierarchy.chain(self.factors_)
        self.L0 = _vec(concatenated(files, "L0"), n, comm)
        self.D = _vec(concatenated(files, "arriving"), n, comm)
        self.exposed = concatenated(files, "exposed")
        self.emits = concatenated(files, "emits").astype(bool)
        self.cast, self.covered = concatenated(files, "closure/cast", np.float64), concatenated(files, "closure/covered", np.float64)
        self.rules = {k: float(v) for k, v in g["balancing"].attrs.items()}
        self.comm = comm
        self.receive, self.send = np.ones(last - first), np.ones(last - first)

    def _apply(self, values, transpose=False):
        """`G x` (or `Gᵀ x`) of this rank's leaves' `values` per cell; its rows summed per leaf."""
        x = self.G.createVecRight() if not transpose else self.G.createVecLeft()
        z = self.G.createVecLeft() if not transpose else self.G.createVecRight()
        x.setArray(np.repeat(values, self.cells))
        (self.G.multTranspose if transpose else self.G.mult)(x, z)
        sums = z.getArray().reshape(-1, self.cells).sum(axis=1)
        x.destroy()
        z.destroy()
        return sums

    def _largest(self, value):
        v = PETSc.Vec().createMPI((1, PETSc.DETERMINE), comm=self.comm)
        v.getArray()[0] = value
        most = v.max()[1]
        v.destroy()
        return most

    def targets(self):
        """Each leaf's row sum to balance to (balanced.rs `closure_targets`): its row `G·1`,
        an emitting leaf's column `Σ_i A_i G_ij / A_j`; the closure rays' share where they
        tell either apart from the closure."""
        rows = self._apply(np.ones(len(self.exposed)))
        own = rows
        if self._largest(float(self.emits.any())) > 0:
            columns = self._apply(self.exposed, transpose=True)
            emitting = self.emits & (self.exposed > 0)
            own = np.where(emitting, columns / np.where(emitting, self.exposed, 1.0), rows)
        share = np.where(self.cast > 0, self.covered / np.maximum(self.cast, 1), 0.0)
        full = self.covered == self.cast
        bar = np.maximum(3.0 * np.sqrt(share * (1.0 - share) / np.maximum(self.cast, 1)), 1.0 / np.maximum(self.cast, 1))
        admits = np.where(full, own == 1.0, np.abs(own - share) <= bar)
        return np.where((self.cast == 0) | admits, own, share)

    def balance(self):
        """The sweeps of balance.rs from factors 1; returns the sweeps and the row mismatch left."""
        r = self.rules
        most, sending = r["most"], 1.0 + r["sending"]
        targets, areas = self.targets(), self.exposed
        free = (targets > 0) & (areas > 0)
        receive, send = np.ones(len(areas)), np.ones(len(areas))

        def mismatch(rows):
            within = (receive > 1.0 / most) & (receive < most) & free
            local = np.abs(receive[within] * rows[within] / targets[within] - 1.0)
            return self._largest(local.max() if len(local) else 0.0)

        def rescale(factors, sums, limit):
            moving = free & (sums > 0)
            nxt = np.clip(targets[moving] / np.where(moving, sums, 1.0)[moving], 1.0 / limit, limit)
            change = np.abs(nxt / factors[moving] - 1.0).max() if moving.any() else 0.0
            factors[moving] = nxt
            return self._largest(change)

        last, sweeps = np.inf, 0
        for sweep in range(1, int(r["max_sweeps"]) + 1):
            rows = self._apply(send)
            m = mismatch(rows)
            stalled = m < r["furnace"] and m > (1.0 - r["stalled"]) * last
            if sweep > 1 and (m < r["rows_balanced"] or stalled):
                break
            last = m
            change = rescale(receive, rows, most)
            columns = self._apply(areas * receive, transpose=True) / np.where(areas > 0, areas, 1.0)
            change = max(change, rescale(send, columns, sending))
            sweeps = sweep
            if change < r["balanced"]:
                break
        residual = mismatch(self._apply(send))
        self.receive, self.send = receive, send
        R, _, P, _ = self.factors_
        scale = R.createVecRight()
        scale.setArray(np.repeat(send, self.cells))
        R.diagonalScale(R=scale)
        scale.setArray(np.repeat(receive, self.cells))
        P.diagonalScale(L=scale)
        scale.destroy()
        return sweeps, residual

    def factors(self):
        """The balancing factors (receiving, sending) as distributed vectors by leaf."""
        out = []
        for values in (self.receive, self.send):
            out.append(_vec(values, self.leaves, self.comm))
        return out


def read(paths, comm=PETSc.COMM_WORLD):
    """The operator of the rows files `paths` over `comm`'s ranks."""
    return Operator(paths, comm)
