#!/usr/bin/env python3
"""The hard-probe benchmark of issue 34 (docs/accuracy.md).

For each room case: place the hard probes by class (`ugo probes`), make the case with them
in place of its own probes (cameras, grids and light scenes dropped, file paths made
absolute), trace the reference into tests/data/accuracy/CASE.csv with the commands in its
header: a pilot (`ugo trace --probe-samples 16384 --seed S`) says how many paths each probe
needs for TARGET standard error, and the probes, grouped by that count (powers of two), are
traced again with seed S + 1 (the pilot only chooses the counts; a large group in chunks,
the k-th with seed S + 1 + k; a trace that ran to the end is kept, and `--step reference`
run again resumes after it); solve it with each setting
(timed, wall clock and peak memory) and write every probe's relative error to
out/accuracy/CASE-SETTING.csv (`--step compare` again from the solves' files); trace the
probes with `ugo trace` in about the case's own solve time, compared like a setting
(`trace-equal`, `--step trace`); and solve the case as it stands, its own probes steering the
refinement, then read the hard probes on that field with `ugo readout` (`unsteered`,
`--step unsteered`: in the solves above the hard probes' own importance refines the links
they read, which a user's probes elsewhere would not). `report.py` turns those into the
tables of docs/accuracy.md.

    tools/accuracy/bench.py cornell-box open-box office            # all three steps
    tools/accuracy/bench.py --step pilot lecture-hall                 # what its references would cost
    tools/accuracy/bench.py --step solve office                       # the solves only
    tools/accuracy/bench.py --step trace cornell-box                  # ugo trace at equal time
    tools/accuracy/bench.py --step unsteered seat-room                # the probes read after the solve
    tools/accuracy/bench.py --step unsteered --setting tolerance-2e-2 office  # … with a setting's flags
    tools/accuracy/bench.py --tuning open-box                         # a second probe set to tune on
    tools/accuracy/bench.py --step solve --ugo B --setting NAME office  # another build, as NAME

`--tuning` places a second, smaller set (`--count 10 --seed 2` unless given), drops every
probe within TUNING_APART of a probe of the committed set, and writes its references to
tests/data/accuracy/tuning/CASE.csv and its files to out/accuracy/tuning/: a parameter is
chosen on that set and reported on the committed one (docs/accuracy.md).

Only the Python standard library: the ugo binary does the work.
"""

import argparse
import csv
import math
import os
import re
import shlex
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
UGO = ROOT / "target" / "release" / "ugo"
OUT = ROOT / "out" / "accuracy"
DATA = ROOT / "tests" / "data" / "accuracy"

# The references' standard error, relative; the pilot's paths per reading, and the most
# paths a reading is given.
TARGET = 0.003
PILOT = 1 << 14
MOST = 1 << 22
# The most probe paths one trace of the references takes (paths × probes; about an hour
# of the lecture hall's on two cores): a larger group is traced in chunks, each kept when
# done (`traced`), the k-th with seed S + 1 + k.
CHUNK = 1 << 23

# The floor of a relative error: a reading is judged (and its reference traced) relative to
# the larger of its own illuminance and this share of the mean illuminance of the room's
# `open` probes. Without it a near-black probe (2 cm between two books) would need 2²² paths
# for a standard error nobody reads, and a solve's 0.01 lx there would count as +300 %.
FLOOR_SHARE = 0.05

# The settings solved per case: a name and the flags of `ugo solve`. "case" is the case's own.
SETTINGS = {
    "cornell-box": [
        ("case", []),
        ("hierarchy", ["--kernel", "hierarchical"]),
        # no `kernel` in the case: at 0.02 m the size rule picks the hierarchy (roots 0.08 m)
        ("leaves-0.02", ["--patch-size", "0.02"]),
        # at the size rule's threshold: a small room whose uniform kernel stays affordable there
        ("uniform-0.1", ["--kernel", "uniform", "--patch-size", "0.1"]),
        ("hierarchy-0.1", ["--kernel", "hierarchical", "--patch-size", "0.1"]),
        ("uniform-0.05", ["--kernel", "uniform", "--patch-size", "0.05"]),
        ("hierarchy-0.05", ["--kernel", "hierarchical", "--patch-size", "0.05"]),
        ("uniform-0.07", ["--kernel", "uniform", "--patch-size", "0.07"]),
        ("hierarchy-0.07", ["--kernel", "hierarchical", "--patch-size", "0.07"]),
    ],
    "glossy-cornell": [
        ("case", []),
        ("hierarchy", ["--kernel", "hierarchical"]),
    ],
    "open-box": [
        ("case", []),
        ("roots-0.12", ["--root-size", "0.12"]),
        ("uniform-0.04", ["--kernel", "uniform", "--patch-size", "0.04"]),
    ],
    "office": [
        ("case", []),
        ("tolerance-2e-2", ["--link-tolerance", "2e-2"]),
        ("tolerance-4e-2", ["--link-tolerance", "4e-2"]),
        ("leaves-0.05", ["--patch-size", "0.05"]),
        ("tolerance-3e-3", ["--link-tolerance", "3e-3"]),
        ("uniform-0.25", ["--kernel", "uniform", "--patch-size", "0.25"]),
    ],
    "daylit-office": [
        # no `kernel` in the case: at its 0.25 m the size rule picks the hierarchy
        ("case", []),
        ("uniform-0.25", ["--kernel", "uniform"]),
        ("uniform-0.15", ["--kernel", "uniform", "--patch-size", "0.15"]),
        ("uniform-0.1", ["--kernel", "uniform", "--patch-size", "0.1"]),
        ("hierarchy-0.15", ["--kernel", "hierarchical", "--patch-size", "0.15"]),
        ("hierarchy-0.1", ["--kernel", "hierarchical", "--patch-size", "0.1"]),
    ],
    "mirror-room": [
        ("case", []),
        ("hierarchy", ["--kernel", "hierarchical"]),
        ("uniform-0.15", ["--kernel", "uniform", "--patch-size", "0.15"]),
    ],
}
DEFAULT_SETTINGS = [("case", [])]

# A tuning set's probes stand at least this far from the committed set's, m (the corner
# classes repeat points, so the two sets would otherwise share some).
TUNING_APART = 0.005

# The tables a benchmark case drops: its own probes (replaced), and what costs time
# without reading a probe.
DROPPED = {"probe", "camera", "grid", "light_scene"}


def run(command, log):
    """Runs `command`, its output to `log`; returns (stdout, wall seconds, peak MB)."""
    start = time.monotonic()
    timed = ["/usr/bin/time", "-f", "%M"] + [str(c) for c in command]
    done = subprocess.run(timed, capture_output=True, text=True)
    seconds = time.monotonic() - start
    log.write_text(done.stdout + done.stderr)
    if done.returncode != 0:
        sys.exit(f"bench: {shlex.join(map(str, command))} failed (exit {done.returncode}), see {log}")
    peak = int(done.stderr.strip().splitlines()[-1]) / 1024
    return done.stdout, seconds, peak


def traced(command, log):
    """`run(command, log)` for a trace of the references, kept: its stdout and seconds. A
    trace whose log and record (the log's name with `.run`: the command and its seconds)
    say it ran to the end with the same arguments (any binary) is read back, not traced
    again, so a reference cut off (hours of tracing) resumes where it stopped."""
    record, arguments = log.with_suffix(".run"), f"# {as_ugo(command)}"
    if log.exists() and record.exists():
        lines = record.read_text().splitlines()
        if lines[0] == arguments:
            return log.read_text(), recorded_seconds(record)
    out, seconds, peak = run(command, log)
    record.write_text(f"{arguments}\n# seconds {seconds:.1f} peak_MB {peak:.0f}\n")
    return out, seconds


def recorded_seconds(record):
    """The wall seconds a run's record (`name.run`: its command, then `# seconds S ...`) holds."""
    return float(record.read_text().split("seconds ")[1].split()[0])


def as_ugo(command):
    """A command of `ugo` as written in a reference's header and its record: `ugo` and its
    arguments, whichever build (`--ugo`) traced it."""
    return f"ugo {shown(command[1:])}"


def shown(command):
    """A command as written in a header: paths relative to the repository."""
    return shlex.join(os.path.relpath(c, ROOT) if isinstance(c, Path) else str(c) for c in command)


def bench_case(case, probes):
    """The case's text without DROPPED tables, its file paths absolute, with the `probes` text."""
    kept, skipping = [], False
    folder = case.parent.resolve()
    for line in case.read_text().splitlines():
        header = re.match(r"^\s*\[\[?\s*([A-Za-z_]+)\s*\]\]?\s*(#.*)?$", line)
        if header:
            skipping = header.group(1) in DROPPED
        if skipping:
            continue
        path = re.match(r'^(\s*file\s*=\s*")([^"]+)(".*)$', line)
        if path and not os.path.isabs(path.group(2)):
            line = path.group(1) + str(folder / path.group(2)) + path.group(3)
        kept.append(line)
    return "\n".join(kept) + "\n\n" + probes


def place(name, count, seed, apart_from=None):
    """`ugo probes`, then the benchmark case; returns (its path, the probes' command).
    With `apart_from` (a reference file), the probes within TUNING_APART of one of its
    probes are left out."""
    case = ROOT / "cases" / f"{name}.toml"
    probes = OUT / f"{name}-probes.toml"
    command = [UGO, "probes", case, "-o", probes, "--count", count, "--seed", seed]
    out, _, _ = run(command, OUT / f"{name}-probes.log")
    print(out, end="")
    text = probes.read_text()
    if apart_from is not None:
        text = apart(text, apart_from)
    bench = OUT / f"{name}-bench.toml"
    bench.write_text(bench_case(case, text))
    return bench, command


def at_committed_probes(name, bench):
    """The benchmark case `bench` with the probes of DATA/name.csv, where its references were
    traced: placement follows the mesh (candidates over the exposed area, moved to walls), so
    a change of either places probes elsewhere under the same names, which must not be
    compared with those references. Says how many moved."""
    with open(DATA / f"{name}.csv") as f:
        rows = list(csv.DictReader(l for l in f if not l.startswith("#")))
    placed = probe_tables(bench)
    moved = sum(1 for r in rows if r["name"] not in placed
                or math.dist(tuple(map(float, placed[r["name"]]["position"])), tuple(float(r[k]) for k in "xyz")) > 1e-6)
    if moved:
        print(f"  {moved} of {len(rows)} probes placed now stand elsewhere than in {os.path.relpath(DATA / f'{name}.csv', ROOT)}: "
              "read at the references' probes")
    tables = "".join(f'\n[[probe]]\nname = "{r["name"]}"\nposition = [{r["x"]}, {r["y"]}, {r["z"]}]\n'
                     f'normal = [{r["nx"]}, {r["ny"]}, {r["nz"]}]\n' for r in rows)
    bench.write_text(bench_case(ROOT / "cases" / f"{name}.toml", tables))
    return bench


def apart(probes, reference):
    """The `[[probe]]` tables of `probes` (a file's text) farther than TUNING_APART from
    every probe of `reference` (a references file)."""
    with open(reference) as f:
        taken = [tuple(float(r[k]) for k in "xyz") for r in csv.DictReader(l for l in f if not l.startswith("#"))]
    tables = probe_tables_of(probes)
    kept = [t["text"] for t in tables.values()
            if min(math.dist(tuple(map(float, t["position"])), p) for p in taken) > TUNING_APART]
    print(f"  {len(kept)} of {len(tables)} probes farther than {TUNING_APART} m from those of {os.path.relpath(reference, ROOT)}")
    return "".join(kept)


def reading_lines(text):
    """(name, L, σL, E, σE) of every probe line `ugo trace` prints."""
    number = r"([-+0-9.eE]+)"
    line = re.compile(rf"^\s+(\S+)\s+{number} ± {number}\s+{number} ± {number}\s*$")
    return [(m[1], *map(float, m.groups()[1:])) for m in map(line.match, text.splitlines()) if m]


def floor_of(readings):
    """FLOOR_SHARE of the mean illuminance of the `open` probes in (name, E) pairs, lx."""
    open_e = [e for probe, e in readings if probe.split("/")[0] == "open"]
    return FLOOR_SHARE * sum(open_e) / len(open_e)


def paths_needed(e, se, floor):
    """Paths for a standard error of TARGET × max(e, floor) from the pilot's σ, a power of two."""
    wanted = PILOT * (se / (TARGET * max(e, floor))) ** 2 * 1.2 if max(e, floor) > 0 else MOST
    return min(MOST, max(2 * PILOT, 1 << max(0, math.ceil(math.log2(wanted)))))


def pilot(name, bench, seed):
    """The pilot: (its command, seconds, the floor, {paths: probes}); prints what the
    references will cost."""
    command = [UGO, "trace", bench, "--probe-samples", PILOT, "--seed", seed]
    out, seconds = traced(command, OUT / f"{name}-pilot.log")
    piloted = reading_lines(out)
    floor = floor_of([(probe, e) for probe, _, _, e, _ in piloted])
    groups = {}
    for probe, _, _, e, se in piloted:
        groups.setdefault(paths_needed(e, se, floor), []).append(probe)
    planned = sum(paths * len(names) for paths, names in groups.items()) / (PILOT * len(piloted))
    print(f"  pilot {seconds:.0f} s; floor {floor:.3g} lx; the references need {planned:.1f} times "
          f"the pilot's paths (about {planned * seconds / 60:.0f} minutes)")
    return command, seconds, floor, groups


def reference(name, bench, placed, seed):
    """Traces the references into DATA/name.csv with the commands in its header."""
    command, seconds, floor, groups = pilot(name, bench, seed)
    tables = probe_tables(bench)
    commands = [f"pilot: {as_ugo(command)} ({seconds:.0f} s)",
                f"paths a probe for a standard error of {TARGET} × max(E, {floor:.4g} lx), the floor "
                f"{FLOOR_SHARE} × the open probes' mean (the pilot's)"]
    readings = []
    case = ROOT / "cases" / f"{name}.toml"
    for paths, names in sorted(groups.items()):
        size = max(1, CHUNK // paths)
        chunks = [names[k:k + size] for k in range(0, len(names), size)]
        for k, chunk in enumerate(chunks):
            part = f"{paths}-{k}" if len(chunks) > 1 else f"{paths}"
            group = OUT / f"{name}-bench-{part}.toml"
            group.write_text(bench_case(case, "".join(tables[n]["text"] for n in chunk)))
            command = [UGO, "trace", group, "--probe-samples", paths, "--seed", seed + 1 + k]
            out, seconds = traced(command, OUT / f"{name}-trace-{part}.log")
            commands.append(f"{len(chunk)} probes: {as_ugo(command)} ({seconds:.0f} s)")
            readings += reading_lines(out)
            print(f"  {len(chunk)} probes at {paths} paths: {seconds:.0f} s", flush=True)
    write_reference(name, placed, commands, readings, tables)


def write_reference(name, placed, commands, readings, tables):
    """DATA/name.csv: the readings by probe, the commands in its header."""
    DATA.mkdir(parents=True, exist_ok=True)
    with open(DATA / f"{name}.csv", "w", newline="") as f:
        f.write(f"# Hard-probe references of cases/{name}.toml (issue 34, docs/accuracy.md).\n")
        f.write(f"# probes: {as_ugo(placed)}\n")
        if DATA.name == "tuning":
            f.write(f"# then every probe within {TUNING_APART} m of one of tests/data/accuracy/{name}.csv left out\n")
        f.write(f"# case: tools/accuracy/bench.py: cases/{name}.toml without its "
                f"{', '.join(sorted(DROPPED))} tables, with the probes (out/accuracy/{name}-bench-PATHS.toml)\n")
        f.writelines(f"# {c}\n" for c in commands)
        f.write("# E_lx: illuminance on a receiver facing the normal; L_cd_m2: what a meter aimed along it reads\n")
        w = csv.writer(f, lineterminator="\n")
        w.writerow(["name", "class", "x", "y", "z", "nx", "ny", "nz", "E_lx", "E_se_lx", "L_cd_m2", "L_se_cd_m2"])
        for probe, l, sl, e, se in sorted(readings, key=lambda r: list(tables).index(r[0])):
            p = tables[probe]
            w.writerow([probe, probe.split("/")[0], *p["position"], *p["normal"], f"{e:.6e}", f"{se:.3e}",
                        f"{l:.6e}", f"{sl:.3e}"])
    print(f"  reference → {os.path.relpath(DATA / f'{name}.csv', ROOT)}")


def probe_tables(bench):
    """name → the `[[probe]]` table of a benchmark case as `ugo probes` writes it (its text,
    position and normal), in the file's order."""
    return probe_tables_of(bench.read_text())


def probe_tables_of(text):
    """`probe_tables` of a file's text."""
    pattern = r'\[\[probe\]\]\nname = "([^"]+)"\nposition = \[([^\]]+)\]\nnormal = \[([^\]]+)\]\n'
    return {m[1]: {"text": "\n" + m[0], "position": m[2].split(", "), "normal": m[3].split(", ")}
            for m in re.finditer(pattern, text)}


def read_reference(name):
    """name → (class, E, σE) from DATA/name.csv."""
    with open(DATA / f"{name}.csv") as f:
        rows = csv.DictReader(line for line in f if not line.startswith("#"))
        return {r["name"]: (r["class"], float(r["E_lx"]), float(r["E_se_lx"])) for r in rows}


def solve(name, bench, setting, flags):
    """Solves the benchmark case with `flags`: its probes' readings in
    out/accuracy/name-setting-probes.csv, the command and its cost in name-setting.run."""
    output = OUT / f"{name}-{setting}.h5"
    command = [UGO, "solve", bench, "-o", output, *flags]
    _, seconds, peak = run(command, OUT / f"{name}-{setting}.log")
    (OUT / f"{name}-{setting}.run").write_text(f"# {shown(command)}\n# seconds {seconds:.1f} peak_MB {peak:.0f}\n")
    output.unlink(missing_ok=True)
    print(f"  {setting}: {seconds:.1f} s, {peak:.0f} MB")


def compare(name, setting):
    """Each probe's error against the reference and its error bar (docs/design.md (5.5)),
    relative to the larger of the reference and the floor: out/accuracy/name-setting.csv."""
    with open(OUT / f"{name}-{setting}-probes.csv") as f:
        solved = {r["name"]: (float(r["E_lx"]), float(r.get("E_error_lx") or "nan")) for r in csv.DictReader(f)}
    ref = read_reference(name)
    floor = floor_of([(probe, e) for probe, (_, e, _) in ref.items()])
    with open(OUT / f"{name}-{setting}.csv", "w", newline="") as f:
        f.write((OUT / f"{name}-{setting}.run").read_text())
        w = csv.writer(f, lineterminator="\n")
        w.writerow(["name", "class", "E_ref_lx", "E_se_lx", "E_lx", "error_pct", "bar_pct"])
        for probe, (cls, e, se) in ref.items():
            x, bar = solved[probe]
            relative = (lambda v: f"{100 * v / max(e, floor):.4f}") if max(e, floor) > 0 else (lambda v: "nan")
            w.writerow([probe, cls, e, se, x, relative(x - e), relative(bar)])


def unsteered(name, bench, flags, tag):
    """Solves cases/name.toml with `flags` and its own readings (`--save-kernel`), then reads
    the benchmark's probes on that field (`ugo readout`): out/accuracy/name-tag-probes.csv,
    the two commands and their cost in name-tag.run, compared like a setting."""
    # the solve's own readings (probe and grid CSVs, plans) go beside it, apart from the settings'
    folder = OUT / "solved"
    folder.mkdir(exist_ok=True)
    case, saved, output = ROOT / "cases" / f"{name}.toml", folder / f"{name}-{tag}.h5", OUT / f"{name}-{tag}.h5"
    solved = [UGO, "solve", case, "-o", saved, "--save-kernel", *flags]
    read = [UGO, "readout", saved, bench, "-o", output, *flags]
    _, solve_seconds, solve_peak = run(solved, folder / f"{name}-{tag}.log")
    _, read_seconds, read_peak = run(read, OUT / f"{name}-{tag}.log")
    (OUT / f"{name}-{tag}.run").write_text(
        f"# {shown(solved)}; {shown(read)}\n"
        f"# seconds {solve_seconds + read_seconds:.1f} peak_MB {max(solve_peak, read_peak):.0f}\n")
    for path in (saved, output):
        path.unlink(missing_ok=True)
    print(f"  {tag}: solve {solve_seconds:.1f} s, readout {read_seconds:.1f} s")
    compare(name, tag)


def header_seconds(text, prefix):
    """The seconds in parentheses on the header line of `text` starting with `prefix`."""
    line = next(l for l in text.splitlines() if l.startswith(prefix))
    return float(re.search(r"\(([0-9.]+) s\)\s*$", line)[1])


def trace_equal(name, bench, seed):
    """`ugo trace` of the benchmark case's probes in about the wall time of the case's own
    solve (out/accuracy/name-case.run): paths per probe from the reference's pilot time,
    scaled and rounded down to a power of two; its readings and error bars (2σ) in
    out/accuracy/name-trace-equal-probes.csv, compared like a setting."""
    case_seconds = recorded_seconds(OUT / f"{name}-case.run")
    pilot_seconds = header_seconds((DATA / f"{name}.csv").read_text(), "# pilot:")
    paths = max(64, 1 << math.floor(math.log2(PILOT * case_seconds / pilot_seconds)))
    command = [UGO, "trace", bench, "--probe-samples", paths, "--seed", seed + 2]
    out, seconds, peak = run(command, OUT / f"{name}-trace-equal.log")
    with open(OUT / f"{name}-trace-equal-probes.csv", "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(["name", "E_lx", "E_error_lx"])
        w.writerows([probe, e, 2 * se] for probe, _, _, e, se in reading_lines(out))
    (OUT / f"{name}-trace-equal.run").write_text(
        f"# {shown(command)}\n# seconds {seconds:.1f} peak_MB {peak:.0f}\n")
    print(f"  trace-equal: {paths} paths a probe, {seconds:.1f} s (the case's solve {case_seconds:.1f} s)")
    compare(name, "trace-equal")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("cases", nargs="+", help="names of cases/NAME.toml")
    parser.add_argument("--step", choices=["all", "pilot", "reference", "solve", "compare", "trace", "unsteered"],
                        default="all",
                        help="pilot: only what the references would cost")
    parser.add_argument("--count", type=int, help="probes per class (20; 10 with --tuning)")
    parser.add_argument("--seed", type=int, help="the probes' seed (1; 2 with --tuning)")
    parser.add_argument("--tuning", action="store_true",
                        help="a second probe set, apart from the committed one, to choose parameters on")
    parser.add_argument("--ugo", type=Path, help="the ugo binary to solve with (target/release/ugo)")
    parser.add_argument("--setting", help="solve and compare only this setting; a name not in the case's "
                                          "settings solves at the case's own (to compare builds)")
    args = parser.parse_args()
    global OUT, DATA, UGO
    UGO = args.ugo or UGO
    committed = DATA
    if args.tuning:
        OUT, DATA = OUT / "tuning", DATA / "tuning"
    count = args.count or (10 if args.tuning else 20)
    seed = args.seed or (2 if args.tuning else 1)
    OUT.mkdir(parents=True, exist_ok=True)
    for name in args.cases:
        print(f"{name}:")
        bench, placed = place(name, count, seed, committed / f"{name}.csv" if args.tuning else None)
        if args.step in ("solve", "compare", "trace", "unsteered") and (DATA / f"{name}.csv").exists():
            bench = at_committed_probes(name, bench)
        if args.step == "pilot":
            pilot(name, bench, seed)
        if args.step in ("all", "reference"):
            reference(name, bench, placed, seed)
        settings = SETTINGS.get(name, DEFAULT_SETTINGS)
        if args.setting:
            settings = [(s, f) for s, f in settings if s == args.setting] or [(args.setting, [])]
        for setting, flags in settings:
            if args.step in ("all", "solve"):
                solve(name, bench, setting, flags)
            if args.step in ("all", "solve", "compare"):
                compare(name, setting)
        if args.step in ("all", "trace"):
            trace_equal(name, bench, seed)
        if args.step in ("all", "unsteered"):
            # the case as it stands, or with the flags of the settings asked for
            for setting, flags in settings if args.setting else [("case", [])]:
                unsteered(name, bench, flags, "unsteered" if setting == "case" else f"unsteered-{setting}")


if __name__ == "__main__":
    main()
