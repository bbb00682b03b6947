#!/usr/bin/python3
"""The hierarchy's operator assembled from its parts' rows files and solved over MPI ranks
(issue 36, point 4; docs/petsc.md, "The operator from the part files").

    ugo solve CASE --part i/n -o links-i.h5                          # each part: its links
    ugo solve CASE --part i/n --linked links-*.h5 -o rows-i.h5        # each part: its rows
    tools/petsc/run -n P --from-parts rows-*.h5 -o OUT.h5 [--against ONE.h5]

Rank r of P reads only the rows files of its parts (n a multiple of P: parts
`[r·n/P, (r+1)·n/P)`, consecutive runs of leaves, nodes and bundles), except the small
arrays every rank needs: each part's bundle keys (to number the bundles as the
one-process operator does, by receiver position and source kind) and the tree (whole, as
hierarchy.py reads it). It assembles `R`, `Λ`, `P` and `B` as distributed AIJ factors
(hierarchy.py), balances `G = P Λ R` to the leaves' closures by the sweeps of ugo's
`balance.rs` (the rules read from the files, each sweep one `G` and one `Gᵀ` across the
ranks), and solves `(I − K) L = L0` by GMRES(30). `--against` compares the field (and,
for a file saved with `--save-kernel`, the balancing factors) with ugo's one-process
solve of the same linking (`ugo solve CASE --passes 1`).
"""

import argparse
import sys
import time

import petsc4py


def arguments(argv):
    p = argparse.ArgumentParser(prog="from_parts.py", description=__doc__.split("\n\n")[0])
    p.add_argument("rows", nargs="+", help="every part's rows file (ugo solve CASE --part i/n --linked …), in any order")
    p.add_argument("-o", "--output", required=True, help="the field and balancing factors as HDF5 (/field/luminance, /balance)")
    p.add_argument("--against", metavar="ONE.h5", help="ugo's one-process solution of the same linking, to compare with")
    p.add_argument("--tolerance", type=float, default=1e-12, help="relative residual of GMRES (default %(default)g)")
    p.add_argument("--max-iterations", type=int, default=1000)
    p.add_argument("--within", type=float, help="with --against: fail unless every value is within this relative difference")
    return p.parse_known_args(argv)


def main():
    args, petsc_options = arguments(sys.argv[1:])
    petsc4py.init([sys.argv[0]] + petsc_options)
    from petsc4py import PETSc

    import parts_operator
    import solvers
    import system
    from solution_file import gather

    comm = PETSc.COMM_WORLD
    say = PETSc.Sys.Print
    start = time.perf_counter()
    op = parts_operator.read(args.rows, comm)
    read_seconds = time.perf_counter() - start
    say(f"from_parts: {len(args.rows)} parts on {comm.getSize()} ranks: {op.leaves} leaves × {op.cells} cells, {op.bundles} bundles, {op.nodes} nodes; read and assembled in {read_seconds:.3f} s")
    start = time.perf_counter()
    sweeps, residual = op.balance()
    say(f"  balanced: {sweeps} sweeps, row error {residual:.1e}, {time.perf_counter() - start:.3f} s")
    run = solvers.solve("gmres:30", system.shell(op.K), op.L0, args.tolerance, args.max_iterations, None)
    say(f"  gmres:30 {run.iterations:>5} iterations  residual {run.residual:.3e}  {run.seconds:8.3f} s  (reason {run.reason})")
    x = gather(run.x)
    receive, send = (gather(v) for v in op.factors())
    failed = None
    if comm.getRank() == 0:
        write(args.output, x, receive, send, op.cells, run, len(args.rows), comm.getSize())
        say(f"  wrote {args.output}")
        if args.against:
            failed = compare(args.against, x, receive, send, op.cells, args.within)
    comm.barrier()
    if failed:
        raise SystemExit(failed)


def write(path, x, receive, send, cells, run, parts, ranks):
    import os

    import h5py

    tmp = f"{path}.tmp"
    with h5py.File(tmp, "w") as f:
        f["field/luminance"] = x.reshape(-1, cells)
        f["balance/receive"], f["balance/send"] = receive, send
        f.attrs.update(iterations=run.iterations, residual=run.residual, parts=parts, ranks=ranks, solver="gmres:30")
    os.replace(tmp, path)


def compare(path, x, receive, send, cells, within):
    """Prints the largest relative differences from ugo's one-process file `path`; says
    why it failed beyond `within` (None within)."""
    import h5py
    import numpy as np

    with h5py.File(path, "r") as f:
        field = f["field/luminance"][:].ravel()
        op = f.get("kernel/hierarchy/operator")
        factors = (op["receive"][:], op["send"][:]) if op is not None else None
    if field.shape != x.shape:
        return (f"from_parts: {path}: {field.size // cells} leaves, the parts {x.size // cells}: not the same linking (ugo solve CASE --passes 1)")
    scale = np.abs(field).max()
    worst = {"field": np.abs(x - field).max() / scale}
    if factors is not None:
        worst["receive"] = np.abs(receive - factors[0]).max()
        worst["send"] = np.abs(send - factors[1]).max()
    print("  against " + path + ": " + ", ".join(f"{k} {v:.2e}" for k, v in worst.items()) + " (largest difference, the field's relative to its largest value)")
    if within is not None and max(worst.values()) > within:
        return f"from_parts: the parts' solution differs from {path} by {max(worst.values()):.2e}, beyond {within:g}"
    return None


if __name__ == "__main__":
    main()
