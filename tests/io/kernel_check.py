"""Rebuilds ugo's kernel K = B·G from a solution file's /kernel group with h5py and scipy
alone, and checks it against ugo (docs/kernel-file.md):

* L0 = L_e + B·D from the stored blocks, direct light and emission;
* the stored solution x against scipy's spsolve of (I − K) x = L0, and x − L0 = K x;
* with an export folder (`ugo export FILE.h5 --format mtx` and `--format petsc`): K, I − K
  and L0 read with scipy.io.mmread and from the PETSc binary files equal the rebuilt ones,
  and ugo's K y equals the rebuilt K y for a random y.

For a hierarchical kernel (`/kernel` attribute `kernel = "hierarchical"`) K is rebuilt as
B · diag(receive) · P · Λ · R · diag(send) from /kernel/hierarchy/operator alone, so every
check above compares those factors with ugo's solution and with ugo's K written out on the
leaves (K.mtx); the exported P, Λ, R, B and diagonals must equal the rebuilt ones.

Every comparison is relative to the largest entry, to 1e-12. Run by tests/io/kernel_file.rs
with Debian's /usr/bin/python3 (python3-h5py, python3-scipy: `make deps`).

    /usr/bin/python3 tests/io/kernel_check.py SOLUTION.h5 [EXPORT_FOLDER]
"""

import os
import sys

import h5py
import numpy as np
import scipy.io
import scipy.sparse as sp
import scipy.sparse.linalg as spla

TOLERANCE = 1e-12
NO_TWIN = 0xFFFFFFFF


def kernel_of(f):
    """K = B·G, L0, the rebuilt L0 and, for a hierarchy, its factors from /kernel."""
    k = f["kernel"]
    b = blocks_of(k)
    factors = None
    if k.attrs.get("kernel") == "hierarchical":
        factors = hierarchy_factors(k, f["directions/projected"][:] / np.pi)
        g = factors["G"]
    else:
        g = sp.csr_matrix((k["G/data"][:], k["G/indices"][:], k["G/indptr"][:]), shape=tuple(k["G"].attrs["shape"]))
    l0 = np.repeat(k["emission"][:], b.shape[0] // len(k["emission"])) + b @ k["direct/arriving"][:]
    if factors is not None:
        factors["B"] = b
    return (b @ g).tocsr(), k["L0"][:], l0, factors


def hierarchy_factors(k, share):
    """G = diag(receive) P Λ R diag(send) from /kernel/hierarchy/operator (docs/kernel-file.md)."""
    factors = hierarchy_parts(k, share)
    P, Lam, R, receive, send = (factors[name] for name in ("P", "Lambda", "R", "receive", "send"))
    factors["G"] = (sp.diags(receive) @ P @ Lam @ R @ sp.diags(send)).tocsr()
    return factors


def hierarchy_parts(k, share):
    """P, Λ, R and the diagonals of G from /kernel/hierarchy/operator, without their
    product (which a large hierarchy cannot hold). Nodes hold S = max(K, 6) values: an
    element's K cells, a cluster's six facing values."""
    h = k["hierarchy/operator"]
    cells = len(share)
    stride = max(cells, 6)
    parent, weight, cluster = h["parent"][:], h["weight"][:], h["cluster"][:].astype(bool)
    facing_share = h["facing_share"][:]
    leaf_position = h["leaf_position"][:]
    nodes, leaves = len(parent), len(leaf_position)
    # push: leaf ← the bundles its ancestors gather, by its share, cell by cell
    indptr, bundle, w = h["push/indptr"][:].astype(np.int64), h["push/bundle"][:], h["push/share"][:]
    gather = h["gather/indptr"][:].astype(np.int64)
    bundles = len(gather) - 1
    leaf_of = np.repeat(np.arange(leaves), np.diff(indptr))
    rows = (leaf_of[:, None] * cells + np.arange(cells)).ravel()
    cols = (bundle.astype(np.int64)[:, None] * cells + np.arange(cells)).ravel()
    P = sp.csr_matrix((np.repeat(w, cells), (rows, cols)), shape=(leaves * cells, bundles * cells))
    # links: bundle ← node value, by cells; d = 65535 arrives from all cells alike (μ_d/π each)
    source, d, m, f = h["gather/source"][:].astype(np.int64), h["gather/d"][:].astype(np.int64), h["gather/m"][:], h["gather/f"][:]
    row_of = np.repeat(np.arange(bundles), np.diff(gather))
    spread = d == 65535
    rows = [(row_of[~spread] * cells + d[~spread])]
    cols = [source[~spread] * stride + m[~spread]]
    vals = [f[~spread]]
    for dd in range(cells):
        rows.append(row_of[spread] * cells + dd)
        cols.append(source[spread] * stride + m[spread])
        vals.append(f[spread] * share[dd])
    Lam = sp.csr_matrix((np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))), shape=(bundles * cells, nodes * stride))
    # pull: node ← area-weighted mean of its leaves; a cluster's six values, each the
    # cell-weighted mean over its elements' exposed area facing one axis direction
    rows, cols, vals = [], [], []
    for leaf, pos in enumerate(leaf_position):
        at, omega, facing = int(pos), 1.0, None
        while True:
            if facing is None:
                rows += [at * stride + c for c in range(cells)]
                vals += [omega] * cells
                cols += [leaf * cells + c for c in range(cells)]
            else:
                for c in range(6):
                    rows += [at * stride + c] * cells
                    vals += list(facing[c] * share)
                    cols += [leaf * cells + m for m in range(cells)]
            if parent[at] == NO_TWIN:
                break
            if facing is not None:
                facing = facing * facing_share[at]
            elif cluster[parent[at]]:
                facing = omega * facing_share[at]
            else:
                omega *= weight[at]
            at = int(parent[at])
    R = sp.csr_matrix((vals, (rows, cols)), shape=(nodes * stride, leaves * cells))
    receive, send = np.repeat(h["receive"][:], cells), np.repeat(h["send"][:], cells)
    return {"P": P, "Lambda": Lam, "R": R, "receive": receive, "send": send}


def blocks_of(k):
    """B over the unknowns from /kernel/B, patch_material and twin."""
    reflect, transmit = k["B/reflection"][:], k["B/transmission"][:]
    material, twin = k["patch_material"][:], k["twin"][:]
    n, cells = len(material), reflect.shape[1]
    rows, cols, vals = [], [], []
    out, inc = np.meshgrid(np.arange(cells), np.arange(cells), indexing="ij")
    for i in range(n):
        # y_i = ρ̄_m(i) z_i + τ̄_m(i) z_twin(i)
        for source, block in ((i, reflect[material[i]]), (twin[i], transmit[material[i]])):
            if source == NO_TWIN or not block.any():
                continue
            rows.append((i * cells + out).ravel())
            cols.append((int(source) * cells + inc).ravel())
            vals.append(block.ravel())
    return sp.csr_matrix((np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))), shape=(n * cells, n * cells))


def petsc_mat(path):
    """A PETSc binary Mat (big-endian, class id 1211216, int32 indices, f64 values)."""
    with open(path, "rb") as fh:
        classid, m, n, nz = np.fromfile(fh, ">i4", 4)
        assert classid == 1211216, f"{path}: class id {classid}"
        lengths = np.fromfile(fh, ">i4", m)
        cols = np.fromfile(fh, ">i4", nz)
        vals = np.fromfile(fh, ">f8", nz)
    indptr = np.concatenate(([0], np.cumsum(lengths)))
    return sp.csr_matrix((vals, cols, indptr), shape=(m, n))


def petsc_vec(path):
    """A PETSc binary Vec (big-endian, class id 1211214)."""
    with open(path, "rb") as fh:
        classid, n = np.fromfile(fh, ">i4", 2)
        assert classid == 1211214, f"{path}: class id {classid}"
        return np.fromfile(fh, ">f8", n)


def relative(a, b):
    """max |a − b| / max |b| for dense or sparse a, b."""
    d = a - b
    d = abs(d).max() if sp.issparse(d) else np.abs(d).max()
    scale = abs(b).max() if sp.issparse(b) else np.abs(b).max()
    return d / scale


def main():
    path = sys.argv[1]
    checks = []
    with h5py.File(path, "r") as f:
        K, L0, rebuilt_l0, factors = kernel_of(f)
        x = f["field/luminance"][:].ravel()
    n = K.shape[0]
    A = (sp.identity(n, format="csr") - K).tocsc()
    checks.append(("L0 = L_e + B·D", relative(rebuilt_l0, L0)))
    checks.append(("spsolve((I - K), L0) against the stored solution", relative(spla.spsolve(A, L0), x)))
    checks.append(("K x against x - L0", relative(K @ x, x - L0)))
    if len(sys.argv) > 2:
        folder = sys.argv[2]
        y = np.random.default_rng(1).random(n)
        if factors is not None:
            for name in ("P", "Lambda", "R", "B"):
                exported = sp.csr_matrix(scipy.io.mmread(os.path.join(folder, f"{name}.mtx")))
                checks.append((f"{name}.mtx against /kernel/hierarchy", relative(exported, factors[name])))
            for name in ("receive", "send"):
                exported = scipy.io.mmread(os.path.join(folder, f"{name}.mtx")).ravel()
                checks.append((f"{name}.mtx against /kernel/hierarchy", relative(exported, factors[name])))
        K_mtx = sp.csr_matrix(scipy.io.mmread(os.path.join(folder, "K.mtx")))
        checks.append(("K.mtx against B·G", relative(K_mtx, K)))
        checks.append(("ugo's K y (K.mtx) against B·G y", relative(K_mtx @ y, K @ y)))
        checks.append(("I-K.mtx against I - B·G", relative(sp.csr_matrix(scipy.io.mmread(os.path.join(folder, "I-K.mtx"))), A)))
        checks.append(("L0.mtx against /kernel/L0", relative(scipy.io.mmread(os.path.join(folder, "L0.mtx")).ravel(), L0)))
        checks.append(("K.petsc against B·G", relative(petsc_mat(os.path.join(folder, "K.petsc")), K)))
        checks.append(("I-K.petsc against I - B·G", relative(petsc_mat(os.path.join(folder, "I-K.petsc")), A)))
        checks.append(("L0.petsc against /kernel/L0", relative(petsc_vec(os.path.join(folder, "L0.petsc")), L0)))
    failed = [(what, e) for what, e in checks if not e <= TOLERANCE]
    for what, e in checks:
        print(f"kernel_check: {what}: {e:.3e}")
    if failed:
        print(f"kernel_check: FAILED beyond {TOLERANCE}: {failed}")
        sys.exit(1)
    print(f"kernel_check: ok, {n} unknowns, {K.nnz} non-zeros of K")


if __name__ == "__main__":
    main()
