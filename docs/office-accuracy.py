#!/usr/bin/env python3
"""Accuracy against time on the furnished office (docs/performance.md, "Accuracy against
time: the office"): `ugo solve cases/office.toml` with the uniform kernel at several patch
sizes and with the hierarchical kernel at the settings a case without `method` would get
(roots 4 h, elements split down to h, link tolerance 1e-2) and at the case's own; per run
the wall clock and peak memory of the whole solve (`/usr/bin/time`: mesh, assembly, solve,
the probes, grid and light scenes, writing), and each probe's illuminance against a
converged backward Monte Carlo reference. Writes docs/img/office-accuracy-vs-time.csv and
the plot (docs/accuracy-plot.py). About 7 minutes on two cores; run from the repository
root after `make build` (UGO=path/to/ugo for another binary).

The reference is `ugo trace` of a copy of the case without its camera,
`--probe-samples 1000000 --seed 11` (5 minutes); its illuminances in lx ± one standard
error, as `ugo trace` printed them.
"""
import csv
import os
import re
import subprocess
import sys

UGO = os.environ.get("UGO", "./target/release/ugo")
OUT = "out/office-accuracy"
CSV = "docs/img/office-accuracy-vs-time.csv"
SVG = "docs/img/office-accuracy-vs-time.svg"
CASE = "cases/office.toml"

REFERENCE = {  # illuminance, lx: (mean, standard error)
    "desk 1, top": (486.6165, 0.161),
    "desk 2, top": (436.0891, 0.159),
    "desk 3, top": (604.7131, 0.153),
    "desk 4, top": (571.5364, 0.151),
    "desk 5, top": (553.1077, 0.155),
    "desk 6, top": (560.2013, 0.158),
    "whiteboard, centre": (590.9161, 0.166),
    "wall z = 0, above the cabinets": (547.1048, 0.164),
    "wall x = 8, by the door": (542.4057, 0.155),
    "wall z = 6, behind the lounge": (540.6561, 0.167),
    "floor, open": (516.0937, 0.154),
    "ceiling, centre": (195.3201, 0.156),
}

# (method, patch size h, link tolerance, smallest): the uniform kernel at h, the hierarchy
# with roots of h
RUNS = [
    ("uniform", 0.5, None, None),
    ("uniform", 0.35, None, None),
    ("uniform", 0.25, None, None),
    ("hierarchical", 2.0, 1e-2, 0.5),
    ("hierarchical", 1.4, 1e-2, 0.35),
    ("hierarchical", 1.0, 1e-2, 0.25),
    ("hierarchical", 1.0, 1e-2, 0.15),
]


def solve(method, h, tolerance, smallest):
    """Runs one solve; returns its log's text (with /usr/bin/time's line last)."""
    args = [UGO, "solve", CASE, "-o", f"{OUT}/x.h5"]
    if method == "hierarchical":
        args += ["--kernel", "hierarchical", "--root-size", str(h), "--link-tolerance", str(tolerance),
                 "--patch-size", str(smallest)]
    else:
        args += ["--kernel", "uniform", "--patch-size", str(h)]
    timed = ["/usr/bin/time", "-f", "wall %e s %M KB"] + args
    run = subprocess.run(timed, capture_output=True, text=True, check=True)
    return run.stdout + run.stderr


def probes(log):
    """The illuminance of each probe as `ugo solve` prints it (the base light, first table)."""
    found = {}
    for line in log.splitlines():
        m = re.match(r"\s{4}(.+?)\s{2,}([\d.]+)\s+([\d.]+)\s+([\d.]+)$", line)
        if m and m.group(1).strip() in REFERENCE and m.group(1).strip() not in found:
            found[m.group(1).strip()] = float(m.group(3))
    missing = set(REFERENCE) - set(found)
    if missing:
        sys.exit(f"the solve printed no illuminance for {sorted(missing)}")
    return found


def row(method, h, tolerance, smallest):
    load = open("/proc/loadavg").read().split()[0]
    log = solve(method, h, tolerance, smallest)
    open(f"{OUT}/{method}-{h}-{tolerance}-{smallest}.log", "w").write(log)
    wall, kb = re.search(r"^wall ([\d.]+) s (\d+) KB", log, re.M).groups()
    leaves = re.search(r"patches N\s+(\d+)", log).group(1)
    errors = {k: 100 * (e / REFERENCE[k][0] - 1) for k, e in probes(log).items()}
    worst = max(errors.values(), key=abs)
    return {
        "method": method, "patch_size_m": h, "link_tolerance": tolerance or "-", "smallest_m": smallest or "-",
        "leaves": leaves, "wall_s": wall, "peak_MiB": f"{int(kb) / 1024:.1f}",
        "ceiling_err_pct": f'{errors["ceiling, centre"]:.3f}',
        "others_worst_err_pct": f'{max((v for k, v in errors.items() if k != "ceiling, centre"), key=abs):.3f}',
        "max_abs_err_pct": f"{abs(worst):.3f}", "load1": load,
    }


def main():
    os.makedirs(OUT, exist_ok=True)
    rows = []
    for run in RUNS:
        rows.append(row(*run))
        print(",".join(str(v) for v in rows[-1].values()), flush=True)
    with open(CSV, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    subprocess.run([sys.executable, "docs/accuracy-plot.py", CSV, SVG, "Furnished office"], check=True)


if __name__ == "__main__":
    main()
