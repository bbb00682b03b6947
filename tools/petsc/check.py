"""The PETSc/SLEPc backend against ugo (`make test-petsc`; docs/petsc.md).

On the glossy Cornell box at 0.1 m patches and 8 direction cells (2,752 unknowns; Phong
and GGX blocks), with `mpiexec -n 2`:

* PETSc's GMRES(5), BiCGSTAB and MUMPS LU solutions agree with ugo's GMRES(5) solution to
  1e-8 (relative to its largest luminance), and so does the illuminance formed from `G`;
* PETSc's GMRES(5) residual history equals ugo's, iteration by iteration, to 1e-14
  (relative residuals, i.e. in units of ‖L0‖₂: round-off), with the same iteration count;
  the shell operator `I − K` over `K` gives the same history;
* SLEPc's ρ(K) agrees with `ugo norms` (power iteration) to 1e-6; the dominant
  eigenvector `v` satisfies `K v = ρ v` for the `K` rebuilt by scipy (tests/io/
  kernel_check.py) to 1e-9 and is non-negative (the Perron vector); the extreme singular
  values of `I − K` equal numpy's dense SVD to 1e-8;
* `ugo render` reads the written file and the one of the dominant eigenvector (`--mode
  1`), and `ugo agree` against a forward trace gives the same per-surface table for
  PETSc's file as for ugo's.

On the opal diffuser (a two-sided transmitting panel: the twins' rows of `G`), read from
`/kernel` and from `ugo export --format petsc`: the direct and GMRES solutions agree with
ugo's direct one to 1e-8.

The hierarchical kernel (the glossy Cornell box with `--kernel hierarchical --root-size
0.4` at 0.1 m and 4 cells: 508 leaves, clusters and spread links; the opal diffuser's
hierarchy for the twins), read as its factors `K = B·P·Λ·R` on 1 and 2 ranks: GMRES(30)
and BiCGSTAB at 1e-13 agree with ugo's direct solution to 1e-10, and so does the
illuminance from the factors; MUMPS on `K` multiplied out leaves a residual under 1e-13;
SLEPc's ρ(K) agrees with `ugo norms` to 1e-6 and `K v = ρ v` holds for scipy's `K` to
1e-9; `direct` beyond `--memory-limit` is refused naming the limit; `ugo render` draws
the written file and `ugo agree` (a forward trace on the leaves, `--bins-of`) prints the
same table for it as for ugo's.

    /usr/bin/python3 tools/petsc/check.py [UGO] [WORK_FOLDER]
"""

import json
import os
import subprocess
import sys
import tempfile

import h5py
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "tests", "io"))
from kernel_check import kernel_of  # noqa: E402

SOLUTION = 1e-8
HISTORY = 1e-14
RHO = 1e-6
CORNELL = ["cases/glossy-cornell.toml", "--patch-size", "0.1", "--directions", "8"]
OPAL = ["cases/opal-diffuser.toml", "--patch-size", "0.1"]
HIERARCHY = ["cases/glossy-cornell.toml", "--kernel", "hierarchical", "--root-size", "0.4", "--patch-size", "0.1", "--directions", "4"]
HIERARCHY_SOLUTION = 1e-10
failures = []


def run(*command):
    done = subprocess.run(command, cwd=ROOT, capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"check_petsc: {' '.join(command)} failed:\n{done.stdout}\n{done.stderr}")
    return done.stdout


def petsc(*args):
    return run(os.path.join(HERE, "run"), "-n", "2", *args)


def check(what, error, limit):
    ok = error <= limit
    print(f"check_petsc: {what}: {error:.3e} (limit {limit:.0e}){'' if ok else '  FAILED'}")
    if not ok:
        failures.append(what)


def field(path, name="field/luminance"):
    with h5py.File(path, "r") as f:
        return f[name][:].ravel()


def relative(a, b):
    return np.abs(a - b).max() / np.abs(b).max()


def fold(history, restart):
    """ugo's GMRES(m) residual record (src/solve/gmres.rs) as one value per iteration, KSP's.

    ugo records the true residual starting every cycle, then the Arnoldi estimate after
    each of up to m iterations, and after the last cycle the true residual once more. KSP
    records, at iteration j, the true residual where a cycle starts (j = 0 and each
    restart) and the estimate elsewhere, the last iteration included.
    """
    values = [history[0]]
    i = 1
    while i < len(history):
        taken = min(restart, len(history) - i - 1)
        values.extend(history[i : i + taken])
        i += taken
        if i < len(history) - 1:
            # A cycle ended at a restart: its last estimate gives way to the true residual.
            values[-1] = history[i]
        i += 1
    return np.array(values)


def cornell(ugo, work):
    mine, theirs = os.path.join(work, "ugo.h5"), os.path.join(work, "petsc.h5")
    report = os.path.join(work, "petsc.json")
    run(ugo, "solve", *CORNELL, "--method", "gmres:5", "--tolerance", "1e-12", "--save-kernel", "-o", mine)
    run(ugo, "norms", *CORNELL, "--kernel-file", mine, "-o", os.path.join(work, "norms.h5"))
    said = petsc(mine, "-o", theirs, "--methods", "gmres:5,bicgstab,direct", "--tolerance", "1e-12",
                 "--eigenvalues", "3", "--mode", "1", "--singular", "--report", report)
    print(said, end="")
    figures = json.load(open(report))
    runs = figures["runs"]
    x = field(mine)
    check("PETSc GMRES(5) solution against ugo's", relative(field(theirs), x), SOLUTION)
    check("illuminance from G against ugo's", relative(field(theirs, "field/illuminance"), field(mine, "field/illuminance")), SOLUTION)
    check("BiCGSTAB's residual", runs["bicgstab"]["residual"], 1e-11)
    check("LU's residual", runs["direct"]["residual"], 1e-13)
    if "mumps" not in runs["direct"]["solver"] and "superlu_dist" not in runs["direct"]["solver"]:
        failures.append(f"the direct solver is {runs['direct']['solver']}, not a parallel LU")
    with h5py.File(mine, "r") as f:
        ugo_history = fold(f["solver/residual_history"][:], 5)
    with h5py.File(os.path.join(work, "norms.h5"), "r") as f:
        rho = f["norms"].attrs["spectral_radius"]
    history = np.array(runs["gmres:5"]["history"])
    if len(history) != len(ugo_history):
        failures.append(f"GMRES(5): PETSc {len(history) - 1} iterations, ugo {len(ugo_history) - 1}")
    else:
        check(f"GMRES(5) residual history ({len(history) - 1} iterations) against ugo's", np.abs(history - ugo_history).max(), HISTORY)
    shell_report = os.path.join(work, "shell.json")
    petsc(mine, "-o", os.path.join(work, "shell.h5"), "--matrix-free", "--methods", "gmres:5", "--tolerance", "1e-12", "--report", shell_report)
    shell = np.array(json.load(open(shell_report))["runs"]["gmres:5"]["history"])
    check("GMRES(5) history, shell I - K against assembled", np.abs(shell - history).max() if len(shell) == len(history) else np.inf, HISTORY)
    check("SLEPc rho(K) against ugo norms", abs(figures["spectral_radius"] - rho) / rho, RHO)
    spectrum(mine, theirs, figures)
    forward = [*CORNELL, "--forward", "--photons", "100000"]
    agreement(ugo, work, mine, [theirs, theirs.removesuffix(".h5") + "-mode-1.h5"], forward)


def spectrum(mine, theirs, figures):
    with h5py.File(mine, "r") as f:
        K = kernel_of(f)[0]
    with h5py.File(theirs, "r") as f:
        v = f["petsc/spectrum/vectors"][..., 0].ravel()
    rho = figures["spectral_radius"]
    check("K v = rho v for the dominant eigenvector", np.abs(K @ v - rho * v).max() / (rho * np.abs(v).max()), 1e-9)
    check("the dominant eigenvector's most negative entry", max(0.0, -v.min()), 1e-9)
    mode = field(theirs.removesuffix(".h5") + "-mode-1.h5")
    check("the mode file's field against /petsc/spectrum/vectors", np.abs(mode - v).max(), 0.0)
    sigma = np.linalg.svd(np.eye(K.shape[0]) - K.toarray(), compute_uv=False)
    s = figures["singular"]
    check("sigma_max(I - K) against numpy's SVD", abs(s["largest"] - sigma[0]) / sigma[0], 1e-8)
    check("sigma_min(I - K) against numpy's SVD", abs(s["smallest"] - sigma[-1]) / sigma[-1], 1e-8)


def agreement(ugo, work, mine, renders, trace):
    """`ugo render` draws each file of `renders` (the glossy Cornell box); `ugo agree`
    against a forward trace (`ugo trace TRACE`) prints the same table for PETSc's file,
    the first of `renders`, as for ugo's `mine`."""
    for path in renders:
        folder = os.path.join(work, "render-" + os.path.basename(path).removesuffix(".h5"))
        run(ugo, "render", path, "-o", folder)
        if not os.path.exists(os.path.join(folder, "glossy-cornell-camera-flat.png")):
            failures.append(f"ugo render wrote no picture of {path}")
    forward = mine.removesuffix(".h5") + "-forward.h5"
    run(ugo, "trace", *trace, "-o", forward)
    tables = [run(ugo, "agree", path, forward).splitlines()[1:] for path in (mine, renders[0])]
    if tables[0] != tables[1] or not tables[0]:
        failures.append(f"ugo agree's table differs between {mine} and {renders[0]}")
    else:
        print(f"check_petsc: ugo agree: the same {len(tables[0])}-line table for ugo's and PETSc's files ({os.path.basename(mine)})")


def opal(ugo, work):
    mine, export = os.path.join(work, "opal.h5"), os.path.join(work, "opal-export")
    run(ugo, "solve", *OPAL, "--method", "direct", "--save-kernel", "-o", mine)
    os.makedirs(export, exist_ok=True)
    run(ugo, "export", mine, "--format", "petsc", "-o", export)
    x = field(mine)
    for source, extra in (("/kernel", []), ("the PETSc export", ["--export", export])):
        for method in ("direct", "gmres:30"):
            out = os.path.join(work, f"opal-{method.replace(':', '-')}-{len(extra)}.h5")
            petsc(mine, "-o", out, "--methods", method, "--tolerance", "1e-12", *extra)
            check(f"opal diffuser, {method} from {source}, against ugo's direct solution", relative(field(out), x), SOLUTION)


def hierarchical(ugo, work):
    """The hierarchical kernel, read as its factors, on 1 and 2 ranks (`hierarchy_ranks`),
    `direct` refused beyond `--memory-limit`, the opal diffuser's twins, and the written
    file drawn by `ugo render` and compared by `ugo agree` as ugo's."""
    mine = os.path.join(work, "hierarchy.h5")
    run(ugo, "solve", *HIERARCHY, "--method", "direct", "--save-kernel", "-o", mine)
    run(ugo, "norms", *HIERARCHY, "--kernel-file", mine, "-o", os.path.join(work, "hierarchy-norms.h5"))
    for ranks in ("1", "2"):
        hierarchy_ranks(work, mine, ranks)
    refused = subprocess.run([os.path.join(HERE, "run"), "-n", "2", mine, "-o", os.path.join(work, "refused.h5"), "--methods", "direct", "--memory-limit", "0.001"],
                             cwd=ROOT, capture_output=True, text=True)
    if refused.returncode == 0 or "beyond the memory limit of 0.00 GiB" not in refused.stderr:
        failures.append(f"hierarchy: direct beyond --memory-limit 0.001 was not refused: {refused.stderr[-300:]}")
    else:
        print(f"check_petsc: hierarchy: {refused.stderr.splitlines()[0]}")
    opal_h, opal_petsc = os.path.join(work, "opal-hierarchy.h5"), os.path.join(work, "opal-hierarchy-petsc.h5")
    run(ugo, "solve", *OPAL, "--kernel", "hierarchical", "--root-size", "0.4", "--method", "direct", "--save-kernel", "-o", opal_h)
    petsc(opal_h, "-o", opal_petsc, "--methods", "gmres:30", "--tolerance", "1e-13")
    check("hierarchy, opal diffuser (twins), 2 ranks: gmres:30 against ugo's direct solution", relative(field(opal_petsc), field(opal_h)), HIERARCHY_SOLUTION)
    trace = [*HIERARCHY[:1], "--directions", "4", "--forward", "--photons", "100000", "--bins-of", mine]
    agreement(ugo, work, mine, [os.path.join(work, "hierarchy-gmres-30-2.h5")], trace)


def hierarchy_ranks(work, mine, ranks):
    """On `ranks` ranks: GMRES(30) (with MUMPS on K multiplied out and the spectrum) and
    BiCGSTAB at 1e-13 against ugo's direct solution, the illuminance from the factors,
    ρ(K) against `ugo norms` and `K v = ρ v` for scipy's K (tests/io/kernel_check.py)."""
    x = field(mine)
    for first, extra in (("gmres:30", ["direct", "--eigenvalues", "2"]), ("bicgstab", [])):
        out, report = (os.path.join(work, f"hierarchy-{first.replace(':', '-')}-{ranks}.{e}") for e in ("h5", "json"))
        said = run(os.path.join(HERE, "run"), "-n", ranks, mine, "-o", out, "--methods", ",".join([first] + extra[:1]),
                   "--tolerance", "1e-13", *extra[1:], "--report", report)
        print(said, end="")
        what = f"hierarchy, {ranks} rank(s)"
        check(f"{what}: {first} on the factors against ugo's direct solution", relative(field(out), x), HIERARCHY_SOLUTION)
        check(f"{what}: illuminance from the factors against ugo's", relative(field(out, "field/illuminance"), field(mine, "field/illuminance")), HIERARCHY_SOLUTION)
        if not extra:
            continue
        figures = json.load(open(report))
        check(f"{what}: the LU's residual on K multiplied out", figures["runs"]["direct"]["residual"], 1e-13)
        with h5py.File(os.path.join(work, "hierarchy-norms.h5"), "r") as f:
            rho = f["norms"].attrs["spectral_radius"]
        s = figures["spectral_radius"]
        check(f"{what}: SLEPc rho(K) against ugo norms", abs(s - rho) / rho, RHO)
        with h5py.File(mine, "r") as f:
            K = kernel_of(f)[0]
        with h5py.File(out, "r") as f:
            v = f["petsc/spectrum/vectors"][..., 0].ravel()
        check(f"{what}: K v = rho v, K from scipy", np.abs(K @ v - s * v).max() / (s * np.abs(v).max()), 1e-9)


def main():
    ugo = os.path.abspath(sys.argv[1]) if len(sys.argv) > 1 else os.path.join(ROOT, "target", "release", "ugo")
    work = sys.argv[2] if len(sys.argv) > 2 else tempfile.mkdtemp(prefix="ugo-petsc-")
    os.makedirs(work, exist_ok=True)
    cornell(ugo, work)
    opal(ugo, work)
    hierarchical(ugo, work)
    if failures:
        sys.exit(f"check_petsc: FAILED: {failures}")
    print("check_petsc: ok")


if __name__ == "__main__":
    main()
