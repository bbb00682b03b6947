"""Writing PETSc's solution as a solution file in ugo's own layout (src/io/hdf5_file.rs),
so that `ugo render`, `ugo agree` and h5py read it as they read ugo's (docs/petsc.md).

The input solution file is copied and, in the copy:

* `/field/luminance` (N × C × 1) is PETSc's solution: all that `ugo render` and `ugo agree`
  read of the field (src/io/read.rs), beside the mesh, scene and emission, which the
  kernel does not change;
* `/field/illuminance` is formed again from it, `E_i = π Σ_d ((G x)(i,d) + D(i,d))`
  (src/readout/illuminance.rs), when `G` was read from `/kernel`, and removed otherwise;
* `/solver/{residual_history,seconds}` and the root attributes `method`, `iterations`,
  `residual`, `solve_seconds` describe PETSc's solve, and `backend` names PETSc, the
  ranks and the solver;
* `/petsc/<method>/residual_history` holds every method run, `/petsc/spectrum` the
  eigenvalues, their errors and eigenvectors (N × C × count, the dominant first) and
  `/petsc/singular` the extreme singular values, when computed;
* the readouts ugo gathers with its ray caster from a field (`/probes`, `/grids`,
  `/energy`) and the records of ugo's own solve (`/compare`, `/solver/applications`) are
  removed: they would describe ugo's field, not this one. `/orders` (partial sums of
  `Kⁿ L0`, a property of the kernel, not of the solver) and `/kernel` are kept.

`write_mode` writes an eigenvector of `K` as the field instead, for `ugo render`.

The file is written under a temporary name and renamed when complete, as ugo does
(src/io/atomic.rs). Only rank 0 writes.
"""

import os
import shutil

import h5py
import numpy as np

REMOVED = ("probes", "grids", "energy", "compare", "solver", "field/illuminance")


def _replace(group, name, values):
    if name in group:
        del group[name]
    group.create_dataset(name, data=values)


def write(source, target, run, x, cells, illuminance=None, runs=(), spectrum=None, vectors=(), singular=None, backend=""):
    """Copies `source` to `target` with `run`'s solution `x`; `illuminance` and the
    eigenvectors `vectors` as numpy arrays gathered on rank 0."""
    temporary = f"{target}.tmp{os.getpid()}"
    shutil.copyfile(source, temporary)
    try:
        with h5py.File(temporary, "r+") as f:
            n = f["field/luminance"].shape[0]
            if x.size != n * cells or f["field/luminance"].shape[1] != cells:
                raise SystemExit(f"ugo_petsc: {source}: /field/luminance has shape {f['field/luminance'].shape}, the kernel {x.size} unknowns of {cells} cells")
            for name in REMOVED:
                if name in f:
                    del f[name]
            f["field/luminance"][...] = x.reshape(n, cells, 1)
            if illuminance is not None:
                f.create_dataset("field/illuminance", data=illuminance)
            solver = f.create_group("solver")
            solver.create_dataset("residual_history", data=np.asarray(run.history, dtype=np.float64))
            solver.create_dataset("seconds", data=np.array([run.seconds]))
            attrs = {
                "method": f"PETSc {run.method}",
                "iterations": float(run.iterations),
                "residual": run.residual,
                "solve_seconds": run.seconds,
                "backend": backend,
            }
            for key, value in attrs.items():
                if key in f.attrs:
                    del f.attrs[key]
                f.attrs[key] = value
            _record(f, runs, spectrum, vectors, singular, n, cells)
        os.replace(temporary, target)
    finally:
        if os.path.exists(temporary):
            os.remove(temporary)


def write_mode(source, target, vector, value, index, cells):
    """Copies the solution file `source` to `target` with eigenvector `index` of `K`
    (eigenvalue `value`, scaled to max |v| = 1) as `/field/luminance`, for `ugo render`.
    The illuminance, a property of a solution, is removed."""
    temporary = f"{target}.tmp{os.getpid()}"
    shutil.copyfile(source, temporary)
    try:
        with h5py.File(temporary, "r+") as f:
            n = f["field/luminance"].shape[0]
            f["field/luminance"][...] = vector.reshape(n, cells, 1)
            for name in ("field/illuminance", "orders"):
                if name in f:
                    del f[name]
            for key, text in (("method", f"SLEPc eigenvector {index} of K"), ("eigenvalue", f"{value.real:.15g} {value.imag:+.3g}i")):
                if key in f.attrs:
                    del f.attrs[key]
                f.attrs[key] = text
        os.replace(temporary, target)
    finally:
        if os.path.exists(temporary):
            os.remove(temporary)


def _record(f, runs, spectrum, vectors, singular, n, cells):
    if "petsc" in f:
        del f["petsc"]
    g = f.create_group("petsc")
    for r in runs:
        m = g.create_group(r.method)
        m.create_dataset("residual_history", data=np.asarray(r.history, dtype=np.float64))
        for key, value in (("iterations", r.iterations), ("seconds", r.seconds), ("residual", r.residual)):
            m.attrs[key] = float(value)
        m.attrs["solver"] = r.solver
    if spectrum is not None:
        s = g.create_group("spectrum")
        s.create_dataset("real", data=spectrum.values.real)
        s.create_dataset("imaginary", data=spectrum.values.imag)
        s.create_dataset("error", data=spectrum.errors)
        stacked = np.stack([v.reshape(n, cells) for v in vectors], axis=-1)
        s.create_dataset("vectors", data=stacked)
        s.attrs["spectral_radius"] = float(abs(spectrum.values[0]))
        s.attrs["seconds"] = spectrum.seconds
    if singular is not None:
        v = g.create_group("singular")
        for key, value in (("largest", singular.largest), ("smallest", singular.smallest)):
            v.attrs[key] = value
        v.attrs["condition_two"] = singular.largest / singular.smallest
        v.attrs["seconds"] = singular.seconds


def gather(vec):
    """A distributed Vec as a numpy array on rank 0 (None elsewhere)."""
    from petsc4py import PETSc

    scatter, whole = PETSc.Scatter.toZero(vec)
    scatter.scatter(vec, whole, addv=PETSc.InsertMode.INSERT, mode=PETSc.ScatterMode.FORWARD)
    values = whole.getArray().copy() if vec.getComm().getRank() == 0 else None
    scatter.destroy()
    whole.destroy()
    return values
