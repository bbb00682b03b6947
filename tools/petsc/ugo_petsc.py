#!/usr/bin/python3
"""ugo's kernel solved by PETSc and SLEPc over MPI ranks (docs/petsc.md).

Reads the kernel `K = B·G` and `L0` saved by `ugo solve CASE --save-kernel` (the `/kernel`
group of the solution file, or with `--export DIR` the PETSc binary files of `ugo export
--format petsc`), or the hierarchical kernel as its factors `K = B·P·Λ·R` (`/kernel/
hierarchy`, hierarchy.py; the Krylov solvers and SLEPc apply them without forming `K`),
then

* solves `(I − K) L = L0` with each method of `--methods`: KSP GMRES(m) and BiCGSTAB
  (no preconditioner, `x_0 = L0`, stopping at `‖r‖₂ ≤ tol·‖L0‖₂`, as ugo's) and `direct`,
  a parallel LU (MUMPS, else SuperLU_dist);
* with `--eigenvalues N`, finds the N eigenvalues of `K` of largest magnitude, `ρ(K)` and
  the dominant eigenvector by SLEPc's Krylov–Schur;
* with `--singular`, the extreme singular values of `I − K` and `cond₂(I − K)`;
* writes the first method's solution as a solution file in ugo's layout (`-o`), which
  `ugo render` and `ugo agree` read, with `--mode J` eigenvector J as the field of a
  second one, and with `--report` the figures as JSON.

    mpiexec -n 2 /usr/bin/python3 tools/petsc/ugo_petsc.py cornell.h5 -o cornell-petsc.h5 \\
        --methods gmres:30,bicgstab,direct --eigenvalues 4 --singular

(`make petsc` installs Debian's petsc4py, slepc4py and OpenMPI; `tools/petsc/run` sets
the environment they need.) Arguments starting with `-` that are not the program's go to
PETSc's options database: the KSPs have the prefixes `gmres_`, `bicgstab_`, `direct_`
(e.g. `-direct_ksp_view`), SLEPc's `spectrum_` and `singular_`.
"""

import argparse
import json
import sys
import time

import petsc4py
import slepc4py


def arguments(argv):
    p = argparse.ArgumentParser(prog="ugo_petsc.py", description=__doc__.split("\n\n")[0])
    p.add_argument("solution", help="ugo's solution file with /kernel (ugo solve CASE --save-kernel)")
    p.add_argument("-o", "--output", help="the solution file to write (default: SOLUTION-petsc.h5)")
    p.add_argument("--export", metavar="DIR", help="read K, I-K and L0 from the PETSc files of `ugo export --format petsc`")
    p.add_argument("--methods", default="gmres:30,bicgstab,direct", help="comma-separated: gmres[:M], bicgstab, direct; the first is written (default %(default)s)")
    p.add_argument("--tolerance", type=float, help="relative residual ‖r‖₂/‖L0‖₂ to stop at (default: the file's `tolerance`)")
    p.add_argument("--max-iterations", type=int, help="most iterations (default: the file's `max_iterations`)")
    p.add_argument("--direct", choices=("mumps", "superlu_dist"), help="the LU package (default: MUMPS if PETSc has it)")
    p.add_argument("--matrix-free", action="store_true", help="apply I - K as a shell operator over K (Krylov and SVD; always so for a hierarchical kernel)")
    p.add_argument("--memory-limit", type=float, metavar="GiB", help="largest memory for a hierarchical K multiplied out for `direct`, all ranks together (default: half the machine's or its control group's)")
    p.add_argument("--eigenvalues", type=int, default=0, metavar="N", help="the N eigenvalues of K of largest magnitude (SLEPc)")
    p.add_argument("--mode", type=int, metavar="J", help="also write eigenvector J (1 = the dominant) as the field of a solution file, for ugo render")
    p.add_argument("--mode-output", metavar="FILE", help="that file (default: OUTPUT without .h5, then -mode-J.h5)")
    p.add_argument("--singular", action="store_true", help="the largest and smallest singular values of I - K")
    p.add_argument("--parts", metavar="LIST", help="instead of --methods, FGMRES preconditioned by block Jacobi by part, for each comma-separated number of parts (a hierarchical file; each a multiple of the ranks); the first is written to OUTPUT, each other N to OUTPUT-parts-N.h5")
    p.add_argument("--inner-tolerance", type=float, metavar="T", help="the relative residual of each block's inner GMRES (default: the square root of --tolerance)")
    p.add_argument("--report", help="write the figures as JSON to this file")
    return p.parse_known_args(argv)


def main():
    args, petsc_options = arguments(sys.argv[1:])
    petsc4py.init([sys.argv[0]] + petsc_options)
    slepc4py.init([sys.argv[0]] + petsc_options)
    from petsc4py import PETSc

    import by_parts
    import hierarchy
    import hyperslabs
    import kernel_read
    import solution_file
    import solvers
    import spectrum
    import system

    comm = PETSc.COMM_WORLD
    say = PETSc.Sys.Print
    methods = [m for m in args.methods.split(",") if m]
    for m in methods:
        solvers.parse(m)
    if args.mode is not None and not 1 <= args.mode <= args.eigenvalues:
        raise SystemExit(f"ugo_petsc: --mode {args.mode} needs --eigenvalues N with N ≥ {args.mode}")
    tolerance, max_iterations = file_settings(args)
    start = time.perf_counter()
    if args.parts:
        kernel, runs, crossings = by_parts.solve(args, tolerance, max_iterations, comm, say, stored)
    elif args.export:
        kernel = kernel_read.from_export(args.export, cells(args.solution), comm)
    elif hierarchy.is_hierarchical(args.solution):
        kernel = hierarchy.from_solution(args.solution, comm)
    else:
        kernel = kernel_read.from_solution(args.solution, comm)
    read_seconds = time.perf_counter() - start
    if args.parts:
        methods, read_seconds = [], float("nan")
    n = kernel.K.getSize()[0]
    package = args.direct or ("mumps" if PETSc.Sys.hasExternalPackage("mumps") else "superlu_dist")
    if not args.parts:
        say(f"ugo_petsc: {args.solution}: {n} unknowns, {stored(kernel)}, {comm.getSize()} ranks; read in {read_seconds:.3f} s")
    if kernel.factors is not None and any(solvers.parse(m)[0] == "direct" for m in methods):
        limit = args.memory_limit * 2**30 if args.memory_limit else hierarchy.memory_limit()
        bound = hierarchy.check_expansion(kernel, args.solution, limit)
        say(f"  direct: K multiplied out on the leaves, at most {bound:.0f} non-zeros (limit {limit / 2**30:.2f} GiB)")
    assembled = None
    iterative = system.shell(kernel.K) if args.matrix_free or kernel.factors is not None else None

    def operator(kind):
        nonlocal assembled
        if kind != "direct" and iterative is not None:
            return iterative
        if assembled is None:
            assembled = system.assembled(kernel)
        return assembled

    runs = runs if args.parts else []
    for m in methods:
        run = solvers.solve(m, operator(solvers.parse(m)[0]), kernel.L0, tolerance, max_iterations, package)
        runs.append(run)
        say(f"  {m:<12} {run.iterations:>5} iterations  residual {run.residual:.3e}  {run.seconds:8.3f} s  ({run.solver}; reason {run.reason})")
    eig = None
    if args.eigenvalues > 0:
        eig = spectrum.eigenvalues(kernel.K, args.eigenvalues)
        say(f"  rho(K)       {abs(eig.values[0]):.12f}  ({len(eig.values)} eigenvalues, Krylov-Schur, {eig.seconds:.3f} s)")
        for v, e in zip(eig.values, eig.errors):
            say(f"    lambda     {v.real:+.12f} {v.imag:+.3e}i   error {e:.1e}")
    sing = None
    if args.singular:
        sing = spectrum.singular_values(operator("gmres"))
        say(f"  sigma(I-K)   max {sing.largest:.12f}  min {sing.smallest:.12f}  cond2 {sing.largest / sing.smallest:.6f}  ({sing.seconds:.3f} s)")
    first = runs[0]
    x = solution_file.gather(first.x)
    illuminance = solution_file.gather(illuminance_of(kernel, first.x)) if kernel.G is not None else None
    vectors = [solution_file.gather(v) for v in eig.vectors] if eig else []
    output = args.output or args.solution.removesuffix(".h5") + "-petsc.h5"
    backend = f"PETSc {'.'.join(map(str, PETSc.Sys.getVersion()))} over {comm.getSize()} MPI ranks: {first.solver}"
    peaks = hyperslabs.per_rank([hyperslabs.peak_resident()], comm)
    if comm.getRank() == 0:
        say(f"  peak resident per rank: {', '.join(f'{p / 1e6:.0f} MB' for p, in peaks)} (before writing)")
        if illuminance is not None:
            illuminance = illuminance_per_patch(illuminance, kernel.cells)
        solution_file.write(args.solution, output, first, x, kernel.cells, illuminance, runs, eig, vectors, sing, backend)
        say(f"  wrote {output} ({first.method})")
        if args.mode is not None:
            mode_output = args.mode_output or f"{output.removesuffix('.h5')}-mode-{args.mode}.h5"
            solution_file.write_mode(output, mode_output, vectors[args.mode - 1], eig.values[args.mode - 1], args.mode, kernel.cells)
            say(f"  wrote {mode_output} (eigenvector {args.mode} as the field)")
        if args.report:
            report(args, n, comm.getSize(), read_seconds, runs, eig, sing, package, peaks, crossings if args.parts else None)
    if args.parts:
        by_parts.write(args.solution, output, runs[1:], kernel.cells, comm, say)
    comm.barrier()


def stored(kernel):
    """What holds `K`: its non-zeros, or those of its factors (the hierarchy)."""
    if kernel.factors is None:
        return f"{kernel.K.getInfo()['nz_used']:.0f} non-zeros of K"
    counts = " + ".join(f"{f.getInfo()['nz_used']:.0f}" for f in kernel.factors[::-1])
    return f"K = B·P·Λ·R with {counts} non-zeros"


def file_settings(args):
    """The tolerance and most iterations: the command line's, else the solution file's."""
    import h5py

    try:
        f = h5py.File(args.solution, "r")
    except OSError as e:
        raise SystemExit(f"ugo_petsc: {args.solution}: {e}")
    with f:
        tolerance = args.tolerance or float(f.attrs.get("tolerance", 1e-8))
        most = args.max_iterations or int(f.attrs.get("max_iterations", 1000))
    return tolerance, most


def cells(path):
    """The direction cells per patch of a solution file (its /field/luminance)."""
    import h5py

    with h5py.File(path, "r") as f:
        return f["field/luminance"].shape[1]


def illuminance_of(kernel, x):
    """`G x + D` per (patch, cell), distributed; summed per patch by `illuminance_per_patch`."""
    arriving = kernel.D.duplicate()
    kernel.G.mult(x, arriving)
    arriving.axpy(1.0, kernel.D)
    return arriving


def illuminance_per_patch(arriving, cells):
    """`E_i = π Σ_d a(i,d)`, lx (src/readout/illuminance.rs)."""
    import numpy as np

    return np.pi * arriving.reshape(-1, cells).sum(axis=1)


def report(args, n, ranks, read_seconds, runs, eig, sing, package, peaks, crossings=None):
    figures = {
        "solution": args.solution,
        "unknowns": n,
        "ranks": ranks,
        "read_seconds": read_seconds,
        "peak_resident_bytes": [p for p, in peaks],
        "direct_package": package,
        "runs": {
            r.method: {
                "iterations": r.iterations,
                "seconds": r.seconds,
                "residual": r.residual,
                "reason": r.reason,
                "solver": r.solver,
                "history": list(r.history),
            }
            for r in runs
        },
    }
    if crossings is not None:
        figures["parts"] = crossings
    if eig is not None:
        figures["eigenvalues"] = [[v.real, v.imag] for v in eig.values]
        figures["eigen_errors"] = list(eig.errors)
        figures["spectral_radius"] = abs(eig.values[0])
        figures["eigen_seconds"] = eig.seconds
    if sing is not None:
        figures["singular"] = {"largest": sing.largest, "smallest": sing.smallest, "seconds": sing.seconds}
    with open(args.report, "w") as fh:
        json.dump(figures, fh, indent=1)


if __name__ == "__main__":
    main()
