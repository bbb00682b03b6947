"""Block Jacobi by part against ugo (`make test-petsc`, after check.py; docs/petsc.md,
"Block Jacobi by part").

On the glossy Cornell box's hierarchy (check.py's `HIERARCHY`: 508 leaves, 4 cells; its
file `hierarchy.h5` when check.py made it with this ugo), solved by ugo's `direct`,
`tools/petsc/run --parts N` (FGMRES, block Jacobi by part, to
1e-13) with N = 1, 2, 4 parts on 1 rank and N = 2, 4 on 2 ranks:

* every solution equals ugo's to 1e-10, relative to the largest luminance;
* with one part the block is the whole operator: FGMRES converges in 1 or 2 outer
  iterations, and no light crosses parts;
* on the opal diffuser's hierarchy (a transmitting panel whose twins lie in different
  parts), each part's `K_pp` equals scipy's `K` (tests/io/kernel_check.py) restricted to
  the part to 1e-12 for 2, 4 and 8 parts, and 2 parts on 2 ranks give ugo's direct
  solution to 1e-10;
* every rank reads, of the hierarchy's links (`gather`) and push, exactly the rows its
  factors and its parts' blocks need (the report's rows read per rank against those
  derived from the file's whole arrays), on the box and the opal diffuser;
* parts that are not a multiple of the ranks, and a file without
  `/kernel/hierarchy/leaves/root_position`, are refused by name.

    /usr/bin/python3 tools/petsc/check_parts.py [UGO] [WORK_FOLDER]
"""

import json
import os
import shutil
import subprocess
import sys
import tempfile

import h5py
import numpy as np

from check import HERE, HIERARCHY, HIERARCHY_SOLUTION, OPAL, ROOT, check, failures, field, relative, run
from kernel_check import NO_TWIN

ROOT_POSITION = "kernel/hierarchy/leaves/root_position"


def by_parts(mine, work, ranks, counts, name="parts"):
    """`tools/petsc/run -n RANKS MINE --parts COUNTS` at 1e-13: per count, the solution
    file, the run's figures and the parts' (the report's)."""
    out, report = (os.path.join(work, f"{name}-{ranks}.{e}") for e in ("h5", "json"))
    said = run(os.path.join(HERE, "run"), "-n", str(ranks), mine, "-o", out, "--parts", ",".join(map(str, counts)), "--tolerance", "1e-13", "--report", report)
    print(said, end="")
    figures = json.load(open(report))
    files = [out] + [f"{out.removesuffix('.h5')}-parts-{c}.h5" for c in counts[1:]]
    return [(f, figures["runs"][f"bjacobi:{c}"], p) for f, c, p in zip(files, counts, figures["parts"])]


def needed_rows(path, count, ranks):
    """Per rank, the distinct rows of `gather` and `push` that its factors of the
    distributed operator and its parts' blocks need with `count` parts on `ranks` ranks,
    from the file's whole arrays (not through hyperslabs.py): the push rows of the rank's
    leaves and of their transmitting twins; the gather rows of its even share of the
    bundles (its rows of Λ) and of every bundle those push rows take."""
    with h5py.File(path, "r") as f:
        k, h = f["kernel"], f["kernel/hierarchy/operator"]
        part = f[ROOT_POSITION][:].astype(np.int64) * count // int(f["kernel/hierarchy"].attrs["roots"])
        twin, material, transmits = k["twin"][:], k["patch_material"][:], k["B/transmits"][:]
        indptr, bundle, bundles = h["push/indptr"][:], h["push/bundle"][:], len(h["gather/indptr"]) - 1
    need = []
    for rank in range(ranks):
        own = np.flatnonzero(part // (count // ranks) == rank)
        behind = twin[own][(twin[own] != NO_TWIN) & (transmits[material[own]] != 0)]
        lit = np.union1d(own, behind)
        taken = np.concatenate([bundle[indptr[leaf] : indptr[leaf + 1]] for leaf in lit])
        base, extra = divmod(bundles, ranks)
        first = rank * base + min(rank, extra)
        share = np.arange(first, first + base + (rank < extra))
        need.append([len(np.union1d(taken, share)), len(lit)])
    return need


def read_only_needed(path, out, ranks, count, part):
    """The rows each rank read (the report's `read`: bytes, gather rows, push rows) are
    exactly the rows it needs (`needed_rows`): a rank reading another's rows, or missing
    one of its own, fails."""
    read = [[int(r[1]), int(r[2])] for r in part["read"]]
    want = needed_rows(path, count, ranks)
    ok = read == want
    print(f"check_parts: {os.path.basename(out)}, {count} parts, {ranks} rank(s): gather and push rows read per rank {read}, needed {want}{'' if ok else '  FAILED'}")
    if not ok:
        failures.append(f"rows read by {count} parts on {ranks} ranks")


def hierarchy_file(ugo, work):
    """check.py's hierarchy (`work/hierarchy.h5`, the same case and solve) when it is newer
    than `ugo`, else solved again."""
    mine = os.path.join(work, "hierarchy.h5")
    if not (os.path.exists(mine) and os.path.getmtime(mine) > os.path.getmtime(ugo)):
        run(ugo, "solve", *HIERARCHY, "--method", "direct", "--save-kernel", "-o", mine)
    return mine


def refused(args, says, what):
    """`tools/petsc/run ARGS` fails saying `says`."""
    done = subprocess.run([os.path.join(HERE, "run"), *args], cwd=ROOT, capture_output=True, text=True)
    if done.returncode == 0 or says not in done.stderr:
        failures.append(f"{what} was not refused with \"{says}\": {done.stderr[-300:]}")
    else:
        print(f"check_parts: refused: {next(line for line in done.stderr.splitlines() if says in line)}")


def blocks_against_scipy(path, counts):
    """Run as `check_parts.py --blocks FILE` with petsc4py: the largest difference between
    part_blocks.py's `K_pp x` and scipy's `K` (tests/io/kernel_check.py) restricted to
    the part, over the parts of each count, relative to the largest `|K x|`."""
    import numpy as np
    import petsc4py

    petsc4py.init([])
    import part_blocks
    import parts
    from kernel_check import kernel_of

    with h5py.File(path, "r") as f:
        K = kernel_of(f)[0].tocsr()
        leaves = len(f["kernel/patch_material"])
    cells = K.shape[0] // leaves
    x = np.random.default_rng(1).random(K.shape[0])
    scale = np.abs(K @ x).max()
    worst = 0.0
    for count in counts:
        bounds = parts.bounds(parts.leaf_parts(path, count), count)
        for block in part_blocks.part_blocks(path, bounds, range(count)):
            rows = slice(block.first * cells, block.last * cells)
            xp, out = block.K.createVecs()
            xp.getArray()[:] = x[rows]
            block.K.mult(xp, out)
            worst = max(worst, np.abs(out.getArray() - K[rows][:, rows] @ x[rows]).max() / scale)
    return worst


def twins(ugo, work):
    """The opal diffuser's hierarchy (check.py's `opal-hierarchy.h5`: a transmitting panel,
    whose twins lie in different parts): `K_pp` against scipy's `K` restricted, and the
    solution by 2 parts on 2 ranks against ugo's direct one."""
    mine = os.path.join(work, "opal-hierarchy.h5")
    if not (os.path.exists(mine) and os.path.getmtime(mine) > os.path.getmtime(ugo)):
        run(ugo, "solve", *OPAL, "--kernel", "hierarchical", "--root-size", "0.4", "--method", "direct", "--save-kernel", "-o", mine)
    env = {"PETSC_DIR": "/usr/lib/petscdir/petsc3.18/x86_64-linux-gnu-real", **os.environ}
    said = subprocess.run(["/usr/bin/python3", os.path.abspath(__file__), "--blocks", mine], cwd=ROOT, capture_output=True, text=True, env=env)
    if said.returncode != 0:
        sys.exit(f"check_parts: the blocks against scipy failed:\n{said.stderr}")
    check("opal diffuser's hierarchy: K_pp against scipy's K restricted to the part (2, 4, 8 parts; twins across parts)", float(said.stdout), 1e-12)
    for out, _, part in by_parts(mine, work, 2, [2], "opal-parts"):
        check("opal diffuser's hierarchy, 2 parts, 2 ranks: against ugo's direct solution", relative(field(out), field(mine)), HIERARCHY_SOLUTION)
        read_only_needed(mine, out, 2, 2, part)


def main():
    if sys.argv[1:2] == ["--blocks"]:
        print(blocks_against_scipy(sys.argv[2], (2, 4, 8)))
        return
    ugo = os.path.abspath(sys.argv[1]) if len(sys.argv) > 1 else os.path.join(ROOT, "target", "release", "ugo")
    work = sys.argv[2] if len(sys.argv) > 2 else tempfile.mkdtemp(prefix="ugo-petsc-parts-")
    os.makedirs(work, exist_ok=True)
    mine = hierarchy_file(ugo, work)
    x = field(mine)
    for ranks, counts in ((1, (1, 2, 4)), (2, (2, 4))):
        for count, (out, figures, part) in zip(counts, by_parts(mine, work, ranks, counts)):
            what = f"block Jacobi by {count} parts, {ranks} rank(s)"
            check(f"{what}: against ugo's direct solution", relative(field(out), x), HIERARCHY_SOLUTION)
            read_only_needed(mine, out, ranks, count, part)
            if count == 1:
                check(f"{what}: outer iterations, the block being the whole operator", figures["iterations"], 2)
                check(f"{what}: light crossing parts", part["crossing_norm"], 0.0)
    twins(ugo, work)
    refused(["-n", "2", mine, "--parts", "3"], "must be a positive multiple of the ranks", "--parts 3 on 2 ranks")
    old = os.path.join(work, "parts-old.h5")
    shutil.copyfile(mine, old)
    with h5py.File(old, "r+") as f:
        del f[ROOT_POSITION]
    refused([old, "--parts", "2"], f"{old}: no /{ROOT_POSITION}", "a file without the roots' positions")
    if failures:
        sys.exit(f"check_parts: FAILED: {failures}")
    print("check_parts: ok")


if __name__ == "__main__":
    main()
