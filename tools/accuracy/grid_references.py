#!/usr/bin/env python3
"""References of a grid's points (issue 34, point 5; docs/accuracy.md, "Error bars").

Puts a probe at every calculation point of a grid (the centres of its cells, as
`Grid::points` has them, facing its normal), makes the benchmark case with them as
bench.py does (the case without its camera, grid, light scene and probe tables), and traces
them with bench.py's pilot and groups into tests/data/accuracy/grids/CASE-GRID.csv, the
commands in its header. A point whose pilot reads 0 lx (inside a solid) is left out.

    tools/accuracy/grid_references.py open-box floor 0.05,0,0.05 0.9,0,0 0,0,0.9 15,15 0,1,0

Only the Python standard library: the ugo binary does the work.
"""

import argparse
import csv
from pathlib import Path

import bench

DATA = bench.DATA / "grids"

# Standard error asked of each point, relative, and the most paths a point is given: a
# grid's points are many, and its bars (1-4 %) far wider than this.
bench.TARGET = 0.004
bench.MOST = 1 << 20


def vector(text):
    return [float(x) for x in text.split(",")]


def points(origin, edge_u, edge_v, resolution):
    """((a, b), position) of every point, row by row along edge_u, as `Grid::points`."""
    nu, nv = resolution
    return [((a, b), [o + u * (a + 0.5) / nu + v * (b + 0.5) / nv for o, u, v in zip(origin, edge_u, edge_v)])
            for b in range(nv) for a in range(nu)]


def probes_text(grid, placed, normal):
    return "".join(f'\n[[probe]]\nname = "{grid}/{a}-{b}"\nposition = [{", ".join(map(repr, p))}]\n'
                   f'normal = [{", ".join(map(repr, normal))}]\n' for (a, b), p in placed)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("case")
    parser.add_argument("grid", help="the grid's name (the probes are GRID/a-b)")
    for key in ["origin", "edge_u", "edge_v"]:
        parser.add_argument(key, type=vector, help="x,y,z in m")
    parser.add_argument("resolution", type=lambda t: [int(x) for x in t.split(",")], help="nu,nv")
    parser.add_argument("normal", type=vector)
    parser.add_argument("--seed", type=int, default=1)
    a = parser.parse_args()
    bench.OUT.mkdir(parents=True, exist_ok=True)
    name = f"{a.case}-{a.grid}"
    case = bench.ROOT / "cases" / f"{a.case}.toml"
    placed = points(a.origin, a.edge_u, a.edge_v, a.resolution)
    case_file = bench.OUT / f"{name}-bench.toml"
    case_file.write_text(bench.bench_case(case, probes_text(a.grid, placed, a.normal)))
    pilot = [bench.UGO, "trace", case_file, "--probe-samples", bench.PILOT, "--seed", a.seed]
    out, seconds, _ = bench.run(pilot, bench.OUT / f"{name}-pilot.log")
    print(f"  pilot: {seconds:.0f} s")
    groups = {}
    for probe, _, _, e, se in bench.reading_lines(out):
        if e > 0:
            groups.setdefault(bench.paths_needed(e, se), []).append(probe)
    at = {f"{a.grid}/{u}-{v}": ((u, v), p) for (u, v), p in placed}
    commands, readings = [f"pilot: {bench.shown(pilot)} ({seconds:.0f} s)"], []
    for paths, names in sorted(groups.items()):
        group = bench.OUT / f"{name}-bench-{paths}.toml"
        group.write_text(bench.bench_case(case, probes_text(a.grid, [at[n] for n in names], a.normal)))
        command = [bench.UGO, "trace", group, "--probe-samples", paths, "--seed", a.seed + 1]
        out, seconds, _ = bench.run(command, bench.OUT / f"{name}-trace-{paths}.log")
        commands.append(f"{len(names)} points: {bench.shown(command)} ({seconds:.0f} s)")
        readings += bench.reading_lines(out)
        print(f"  {len(names)} points at {paths} paths: {seconds:.0f} s")
    DATA.mkdir(parents=True, exist_ok=True)
    with open(DATA / f"{name}.csv", "w", newline="") as f:
        f.write(f"# References of the points of a grid in cases/{a.case}.toml (issue 34, point 5, docs/accuracy.md).\n")
        f.write(f"# made by: tools/accuracy/grid_references.py {a.case} {a.grid} "
                f"{' '.join(','.join(map(str, v)) for v in [a.origin, a.edge_u, a.edge_v, a.resolution, a.normal])}"
                f" --seed {a.seed}\n")
        f.writelines(f"# {c}\n" for c in commands)
        f.write("# points whose pilot read 0 lx (inside a solid) are left out; E_lx on a receiver facing the normal\n")
        w = csv.writer(f, lineterminator="\n")
        w.writerow(["u", "v", "x", "y", "z", "E_lx", "E_se_lx"])
        for probe, _, _, e, se in sorted(readings, key=lambda r: at[r[0]][0][::-1]):
            (u, v), p = at[probe]
            w.writerow([u, v, *(f"{x:.9f}" for x in p), f"{e:.6e}", f"{se:.3e}"])
    print(f"  reference → tests/data/accuracy/grids/{name}.csv")


if __name__ == "__main__":
    main()
