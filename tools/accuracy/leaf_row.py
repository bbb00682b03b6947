#!/usr/bin/env python3
"""Where one leaf's light comes from in a hierarchical solve (issue 34; docs/hierarchy.md,
"Clear links pushed into umbrae").

    tools/accuracy/leaf_row.py OUT.h5 --at X Y Z NX NY NZ [--forward FORWARD.h5] [--top 6]
    tools/accuracy/leaf_row.py OUT.h5 --leaf 3701

OUT.h5 is a solve with `--save-kernel`: its operator `G = diag(receive) P Λ R diag(send)`
(docs/kernel-file.md; the factors as `tests/io/kernel_check.py` builds them) applied to the
solved luminance gives every leaf's arriving light; `π` times it plus the direct light must
be the stored illuminance (checked to 1e-9 relative, else the script fails). For the leaf
(given by index, or the leaf whose patch holds the point and faces the normal) it prints,
bundle by bundle of its ancestors, the leaf's share of the bundle, the illuminance it takes
from it, and the sources that give most of it: each source node's factor, mean luminance
and the surfaces and extent of the leaves under it (a cluster by the facing value the link
takes: `+x` … `−z`, docs/design.md (3b.7)). With `--forward`, the leaf's bin of
`ugo trace --forward --bins-of OUT.h5` beside it. One cell (K = 1) only.

h5py, numpy and scipy (Debian's python3-h5py, python3-scipy: `make deps`).
"""

import argparse
import sys
from pathlib import Path

import h5py
import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "tests" / "io"))
from kernel_check import hierarchy_parts  # noqa: E402

NO_PARENT = 0xFFFFFFFF
# A node's values in Λ's columns: K = 1 cell of an element, six facing values of a cluster.
STRIDE = 6
FACING = ("+x", "−x", "+y", "−y", "+z", "−z")


def leaf_at(mesh, point, normal):
    """The leaf whose patch's bounding box holds `point` (within 2 mm) facing `normal`, the
    nearest centroid among several."""
    corners = mesh["vertices"][:]
    lo, hi = corners.min(axis=1) - 2e-3, corners.max(axis=1) + 2e-3
    facing = mesh["normals"][:] @ normal > 0.99
    candidates = np.flatnonzero(np.all((lo <= point) & (point <= hi), axis=1) & facing)
    if len(candidates) == 0:
        sys.exit(f"leaf_row: no leaf at {point} facing {normal}")
    centroids = mesh["points"][:][candidates]
    return int(candidates[np.argmin(np.linalg.norm(centroids - point, axis=1))])


def under_each_node(parent, leaf_position, mesh):
    """Per node position: the surfaces and the extent (min, max of centroids) of its leaves."""
    names = [n.decode() for n in mesh["surface_names"][:]]
    surface, points = mesh["surface_id"][:], mesh["points"][:]
    nodes = len(parent)
    lo, hi = np.full((nodes, 3), np.inf), np.full((nodes, 3), -np.inf)
    surfaces = [set() for _ in range(nodes)]
    for leaf, at in enumerate(leaf_position):
        at = int(at)
        while True:
            lo[at], hi[at] = np.minimum(lo[at], points[leaf]), np.maximum(hi[at], points[leaf])
            surfaces[at].add(names[surface[leaf]])
            if parent[at] == NO_PARENT:
                break
            at = int(parent[at])
    return surfaces, lo, hi


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("solution", type=Path, help="a solve's HDF5 file, written with --save-kernel")
    where = parser.add_mutually_exclusive_group(required=True)
    where.add_argument("--leaf", type=int, help="the leaf's index (its patch in /mesh)")
    where.add_argument("--at", type=float, nargs=6, metavar=("X", "Y", "Z", "NX", "NY", "NZ"),
                       help="a point and the normal its leaf faces")
    parser.add_argument("--forward", type=Path, help="ugo trace --forward --bins-of SOLUTION's file")
    parser.add_argument("--top", type=int, default=6, help="sources shown per bundle")
    args = parser.parse_args()
    with h5py.File(args.solution, "r") as f:
        if "kernel" not in f or f["kernel"].attrs.get("kernel") != "hierarchical":
            sys.exit(f"leaf_row: {args.solution} holds no hierarchical kernel (solve with --save-kernel)")
        share = f["directions/projected"][:] / np.pi
        if len(share) != 1:
            sys.exit(f"leaf_row: {len(share)} direction cells; only K = 1 is explained")
        parts = hierarchy_parts(f["kernel"], share)
        x = f["field/luminance"][:].ravel()
        direct, stored = f["field/direct_illuminance"][:], f["field/illuminance"][:]
        op = f["kernel/hierarchy/operator"]
        parent, leaf_position, cluster = op["parent"][:], op["leaf_position"][:], op["cluster"][:].astype(bool)
        mesh = f["mesh"]
        leaf = args.leaf if args.leaf is not None else leaf_at(mesh, np.array(args.at[:3]), np.array(args.at[3:]))
        surfaces, lo, hi = under_each_node(parent, leaf_position, mesh)
        name = mesh["surface_names"][mesh["surface_id"][leaf]].decode()
        at = mesh["points"][leaf]
    P, Lam, R, receive, send = (parts[k] for k in ("P", "Lambda", "R", "receive", "send"))
    mean = R @ (send * x)
    gathered = Lam @ mean
    arriving = receive * (P @ gathered)
    error = np.abs(np.pi * arriving + direct - stored).max() / max(np.abs(stored).max(), 1e-300)
    print(f"leaf_row: the factors reproduce the stored illuminance to {error:.1e} (relative to its largest)")
    if error > 1e-9:
        sys.exit("leaf_row: the saved operator does not reproduce the solved field")
    line = f"leaf {leaf} ({name}) at {np.round(at, 4)}: E {stored[leaf]:.3f} lx, direct {direct[leaf]:.3f} lx"
    if args.forward:
        with h5py.File(args.forward, "r") as g:
            e, se = g["field/illuminance"][:].ravel()[leaf], g["field/illuminance_standard_error"][:].ravel()[leaf]
        line += f"; forward bin {e:.3f} ± {se:.3f} lx"
    print(line + f"; receiving factor {receive[leaf]:.3f}")
    row = P.getrow(leaf)
    for b, w in sorted(zip(row.indices, row.data), key=lambda bw: -bw[1] * gathered[bw[0]]):
        taken = np.pi * receive[leaf] * w * gathered[b]
        print(f"  bundle {b}: share {w:.3f} of {np.pi * gathered[b]:.3f} lx gathered → {taken:.3f} lx")
        links = Lam.getrow(b)
        parts_of = sorted(zip(links.indices, links.data), key=lambda qf: -qf[1] * mean[qf[0]])
        for column, factor in parts_of[: args.top]:
            light = np.pi * receive[leaf] * w * factor * mean[column]
            q, value = divmod(column, STRIDE)
            facing = f" facing {FACING[value]}" if cluster[q] else ""
            extent = f"{np.round(lo[q], 2)}–{np.round(hi[q], 2)}"
            print(f"      source {q}{facing}: F {factor:.4f}, L̄ {mean[column]:.3f} cd/m² → {light:.3f} lx "
                  f"[{', '.join(sorted(surfaces[q]))[:60]}] {extent}")


if __name__ == "__main__":
    main()
