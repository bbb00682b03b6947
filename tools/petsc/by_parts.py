"""`tools/petsc/run SOLUTION.h5 --parts N[,N…]` (issue 36, point 4; docs/petsc.md, "Block
Jacobi by part"): for each number of parts, the saved hierarchy read with its leaves laid
out by part (parts.py), its diagonal blocks (part_blocks.py), the solve by FGMRES with
block Jacobi by part (block_jacobi.py) and the light crossing parts (crossing.py); and the
solution of every number of parts but the first as its own solution file.

petsc4py 3.18 does not free a PETSc object whose last Python reference is dropped (it
waits for a collective `garbage_cleanup`, and objects held by a shell's Python context
outlive that), so each number of parts destroys its blocks, solvers and, but for the
first, its kernel when done: without it the office's run with 2, 4, 8, 16 parts grew by
70–100 MB per number of parts per rank.
"""

import time

import numpy as np
from petsc4py import PETSc

import block_jacobi
import hierarchy
import hyperslabs
import part_blocks
import parts
import solution_file
import system
from crossing import crossing


def solve(args, tolerance, max_iterations, comm, say, stored):
    """FGMRES with block Jacobi by part for each number of parts of `--parts`: the first's
    kernel (its leaves laid out by its parts), the runs and, per run, the inner iterations,
    the seconds spent reading, what each rank read (`Record.summary`) and its peak
    resident memory so far, and the light crossing parts; `stored(kernel)` describes the
    kernel's factors for the first line."""
    if not hierarchy.is_hierarchical(args.solution):
        raise SystemExit(f"ugo_petsc: {args.solution}: --parts needs a hierarchical kernel (ugo solve CASE --kernel hierarchical --save-kernel)")
    counts = [int(c) for c in args.parts.split(",") if c]
    inner = args.inner_tolerance or tolerance**0.5
    first, runs, crossings = None, [], []
    for count in counts:
        mine = parts.parts_of_rank(count, comm)
        start = time.perf_counter()
        bounds = parts.bounds(parts.leaf_parts(args.solution, count), count)
        leaves = (int(bounds[mine.start]), int(bounds[mine.stop]))
        record = hyperslabs.Record()
        kernel = hierarchy.from_solution(args.solution, comm, leaves, record)
        blocks = part_blocks.part_blocks(args.solution, bounds, mine, record)
        read = time.perf_counter() - start
        if first is None:
            first = kernel
            say(f"ugo_petsc: {args.solution}: {kernel.K.getSize()[0]} unknowns, {stored(kernel)}, {comm.getSize()} ranks")
        A = system.shell(kernel.K)
        run, inner_total = block_jacobi.solve(count, A, kernel.L0, blocks, leaves[0], kernel.cells, tolerance, inner, max_iterations)
        norm, light = crossing(kernel.K, blocks, leaves[0], kernel.cells, run.x)
        sizes = np.diff(bounds)
        say(f"  {count:>3} parts ({sizes.min()}–{sizes.max()} leaves)  {run.iterations:>4} outer  {inner_total:>6.0f} inner iterations  "
            f"residual {run.residual:.3e}  {run.seconds:8.3f} s (read {read:.3f} s)  crossing ‖K_off x‖/‖K x‖ {norm:.4f}, light {light:.4f}  (reason {run.reason})")
        if run.reason <= 0:
            raise SystemExit(1 if comm.getRank() else f"ugo_petsc: {args.solution}: block Jacobi by {count} parts did not converge (reason {run.reason})")
        runs.append(run)
        crossings.append({"parts": count, "inner_iterations": inner_total, "read_seconds": read, "crossing_norm": norm, "crossing_light": light,
                          "read": hyperslabs.per_rank(record.summary() + [hyperslabs.peak_resident()], comm)})
        for obj in blocks + [A] + ([kernel] if kernel is not first else []):
            obj.destroy()
    return first, runs, crossings


def write(solution, output, runs, cells, comm, say):
    """Each of `runs` (block Jacobi by another number of parts than the first) as its own
    solution file, `OUTPUT-parts-N.h5`, without the illuminance."""
    for run in runs:
        x = solution_file.gather(run.x)
        if comm.getRank() == 0:
            path = f"{output.removesuffix('.h5')}-parts-{run.method.split(':')[1]}.h5"
            backend = f"PETSc {'.'.join(map(str, PETSc.Sys.getVersion()))} over {comm.getSize()} MPI ranks: {run.solver}"
            solution_file.write(solution, path, run, x, cells, None, [run], backend=backend)
            say(f"  wrote {path} ({run.method})")
