"""Block Jacobi by part against ugo (`make test-petsc`, after check.py; docs/petsc.md,
"Block Jacobi by part").

On the glossy Cornell box's hierarchy (check.py's `HIERARCHY`: 508 leaves, 4 cells; its
file `hierarchy.h5` when check.py made it with this ugo), solved by ugo's `direct`,
`tools/petsc/run --parts N` (FGMRES, block Jacobi by part, to
1e-13) with N = 1, 2, 4 parts on 1 rank and N = 2, 4 on 2 ranks:

* every solution equals ugo's to 1e-10, relative to the largest luminance;
* with one part the block is the whole operator: FGMRES converges in 1 or 2 outer
  iterations, and no light crosses parts;
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

from check import HERE, HIERARCHY, HIERARCHY_SOLUTION, ROOT, check, failures, field, relative, run

ROOT_POSITION = "kernel/hierarchy/leaves/root_position"


def by_parts(mine, work, ranks, counts):
    """`tools/petsc/run -n RANKS MINE --parts COUNTS` at 1e-13: per count, the solution
    file, the run's figures and the parts' (the report's)."""
    out, report = (os.path.join(work, f"parts-{ranks}.{e}") for e in ("h5", "json"))
    said = run(os.path.join(HERE, "run"), "-n", str(ranks), mine, "-o", out, "--parts", ",".join(map(str, counts)), "--tolerance", "1e-13", "--report", report)
    print(said, end="")
    figures = json.load(open(report))
    files = [out] + [f"{out.removesuffix('.h5')}-parts-{c}.h5" for c in counts[1:]]
    return [(f, figures["runs"][f"bjacobi:{c}"], p) for f, c, p in zip(files, counts, figures["parts"])]


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


def main():
    ugo = os.path.abspath(sys.argv[1]) if len(sys.argv) > 1 else os.path.join(ROOT, "target", "release", "ugo")
    work = sys.argv[2] if len(sys.argv) > 2 else tempfile.mkdtemp(prefix="ugo-petsc-parts-")
    os.makedirs(work, exist_ok=True)
    mine = hierarchy_file(ugo, work)
    x = field(mine)
    for ranks, counts in ((1, (1, 2, 4)), (2, (2, 4))):
        for count, (out, figures, part) in zip(counts, by_parts(mine, work, ranks, counts)):
            what = f"block Jacobi by {count} parts, {ranks} rank(s)"
            check(f"{what}: against ugo's direct solution", relative(field(out), x), HIERARCHY_SOLUTION)
            if count == 1:
                check(f"{what}: outer iterations, the block being the whole operator", figures["iterations"], 2)
                check(f"{what}: light crossing parts", part["crossing_norm"], 0.0)
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
