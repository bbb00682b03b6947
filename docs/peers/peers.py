#!/usr/bin/env python3
"""Times ugo's benchmark work with its peers: the same occlusion rays through Embree 4
(the `embreex` package) and the same sparse matrix-vector product through scipy.sparse.

    pip install embreex scipy          # numpy comes with them
    ./target/release/ugo bench --export out/peers
    python3 docs/peers/peers.py out/peers

Prints rays/s (and the fraction of rays on which Embree and ugo agree), GB/s of matrix
traffic (values + column indices + row pointers, as `ugo bench` counts it), and the
ratios to ugo's figures stored in meta.json by the same `ugo bench` run.
"""
import json
import sys
import time
from pathlib import Path

import numpy as np


def best(repeats, f):
    times = []
    for _ in range(repeats):
        t = time.perf_counter()
        result = f()
        times.append(time.perf_counter() - t)
    return min(times), result


def main(folder):
    d = Path(folder)
    meta = json.loads((d / "meta.json").read_text())
    tris = np.fromfile(d / "triangles.f32", dtype="<f4").reshape(-1, 3, 3)
    rays = np.fromfile(d / "rays.f32", dtype="<f4").reshape(-1, 8)
    ugo_visible = np.fromfile(d / "visible.u8", dtype=np.uint8).astype(bool)

    from embreex import rtcore_scene as rtcs
    from embreex.mesh_construction import TriangleMesh

    scene = rtcs.EmbreeScene()
    TriangleMesh(scene, tris)
    # embreex has no tnear: start each ray at tnear and shorten it by as much.
    origins = np.ascontiguousarray(rays[:, 0:3] + rays[:, 3:6] * rays[:, 6:7])
    directions = np.ascontiguousarray(rays[:, 3:6])
    lengths = np.ascontiguousarray(rays[:, 7] - rays[:, 6])
    seconds, hit = best(3, lambda: scene.run(origins, directions, dists=lengths, query="OCCLUDED"))
    embree_visible = np.asarray(hit) < 0
    embree_rate = len(rays) / seconds
    agree = np.mean(embree_visible == ugo_visible)
    print(f"occlusion rays: Embree (embreex) {embree_rate:.3e} rays/s, ugo {meta['ugo_occlusion_rays_per_second']:.3e} rays/s "
          f"on {meta['threads']} threads; ugo/Embree = {meta['ugo_occlusion_rays_per_second'] / embree_rate:.2f}; "
          f"answers agree on {100 * agree:.3f} % of {len(rays)} rays")
    one = meta.get("ugo_occlusion_rays_per_second_one_thread")
    if one:
        # embreex traces its batch on one thread: this is the per-core ratio.
        print(f"occlusion rays per core: ugo {one:.3e} rays/s on one thread; ugo/Embree per core = {one / embree_rate:.2f}")

    import scipy.sparse as sp

    indptr = np.fromfile(d / "csr_indptr.u64", dtype="<u8").astype(np.int64)
    indices = np.fromfile(d / "csr_indices.u64", dtype="<u8").astype(np.int64)
    data = np.fromfile(d / "csr_data.f64", dtype="<f8")
    n = meta["rows"]
    a = sp.csr_matrix((data, indices, indptr), shape=(n, n))
    x = np.ones(n)
    seconds, _ = best(10, lambda: a @ x)
    traffic = data.nbytes + indices.nbytes + indptr.nbytes
    a32 = sp.csr_matrix((data, indices.astype(np.int32), indptr.astype(np.int32)), shape=(n, n))
    seconds32, _ = best(10, lambda: a32 @ x)
    traffic32 = data.nbytes + 4 * len(indices) + 4 * len(indptr)
    print(f"sparse product: scipy {traffic / seconds / 1e9:.2f} GB/s ({seconds * 1e3:.2f} ms, int64 indices), "
          f"{traffic32 / seconds32 / 1e9:.2f} GB/s ({seconds32 * 1e3:.2f} ms, int32 indices); "
          f"ugo {meta['ugo_spmv_seconds'] * 1e3:.2f} ms: ugo/scipy time ratio {seconds / meta['ugo_spmv_seconds']:.2f}× faster")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "out/peers")
