#!/usr/bin/python3
"""The flux each face of each surface receives, of solves against `ugo trace --forward`:
per (surface, facing) the sum of `E A` over its leaves (or patches), relative to the
forward reference's, with that sum's standard error. A face's flux does not depend on how
it is cut into leaves, so solves of different leaves compare with one reference, and a sum
over a face is precise where single bins are not (docs/accuracy.md, "The office leaf by
leaf").

    tools/accuracy/faces.py FORWARD.h5 SOLUTION.h5 [SOLUTION.h5 ...] [--rows 40]

Prints the faces by |error| × sqrt(area) of the first solution, then per solution the
area-weighted mean |error| over the faces and how many are beyond 5 %. h5py and numpy
(Debian's python3-h5py, python3-numpy).
"""

import argparse

import h5py
import numpy as np


def faces(path):
    """(surface name, rounded normal) → [area, Σ E A, Σ (σ_E A)²] of one HDF5 field."""
    with h5py.File(path, "r") as h:
        names = [x.decode() for x in h["mesh/surface_names"][:]]
        surface = h["mesh/surface_id"][:]
        normals = np.round(h["mesh/normals"][:], 2)
        area = h["mesh/exposed_areas"][:]
        e = h["field/illuminance"][:]
        se = h["field/illuminance_standard_error"][:] if "field/illuminance_standard_error" in h else 0 * e
    out = {}
    for i in range(len(surface)):
        sums = out.setdefault((names[surface[i]], tuple(normals[i])), [0.0, 0.0, 0.0])
        sums[0] += area[i]
        sums[1] += area[i] * e[i]
        sums[2] += (area[i] * se[i]) ** 2
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("forward", help="ugo trace --forward's HDF5 file")
    parser.add_argument("solutions", nargs="+", help="ugo solve's HDF5 files of the same case")
    parser.add_argument("--rows", type=int, default=40, help="faces printed")
    args = parser.parse_args()
    reference = faces(args.forward)
    solved = [faces(p) for p in args.solutions]
    rows = []
    for key, (area, flux, variance) in reference.items():
        if flux > 0:
            errors = [100 * (s[key][1] / flux - 1) if key in s else float("nan") for s in solved]
            rows.append((key, area, flux / area, 100 * np.sqrt(variance) / flux, errors))
    rows.sort(key=lambda r: -abs(r[4][0]) * np.sqrt(r[1]))
    for (surface, normal), area, e, se, errors in rows[: args.rows]:
        shown = " ".join(f"{x:+7.1f} %" for x in errors)
        print(f"{surface:30s} {str(normal):22s} {area:7.3f} m² {e:8.1f} lx ± {se:5.2f} % {shown}")
    area = np.array([r[1] for r in rows])
    for k, path in enumerate(args.solutions):
        error = np.array([abs(r[4][k]) for r in rows])
        known = ~np.isnan(error)
        mean = (area[known] * error[known]).sum() / area[known].sum()
        print(f"{path}: area-weighted mean |error| {mean:.2f} %, {(error[known] > 5).sum()} of {known.sum()} faces beyond 5 %")


if __name__ == "__main__":
    main()
