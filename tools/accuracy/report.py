#!/usr/bin/python3
"""The tables and the plot of docs/accuracy.md from the files `bench.py` writes: for each
case and setting (out/accuracy/CASE-SETTING.csv), per class of probes the largest, the
95th-percentile and the mean of |relative error| against the reference, in % of it, and
how many probes lie beyond 1 %, and how many lie within their error bar (docs/design.md
(5.5)) with the mean bar; with the setting's command, wall time and peak memory.

    tools/accuracy/report.py cornell-box open-box office [--plot docs/img/accuracy-vs-time.png]

numpy, and matplotlib for the plot (Debian's python3-numpy, python3-matplotlib).
"""

import argparse
import csv
from pathlib import Path

import numpy as np

OUT = Path(__file__).resolve().parents[2] / "out" / "accuracy"


def load(path):
    """(command, seconds, peak MB, {class: [(error %, bar %)]}) of one solve's file."""
    lines = path.read_text().splitlines()
    command = lines[0].lstrip("# ")
    fields = lines[1].lstrip("# ").split()
    seconds, peak = float(fields[1]), float(fields[3])
    errors = {}
    for row in csv.DictReader(lines[2:]):
        errors.setdefault(row["class"], []).append((float(row["error_pct"]), float(row.get("bar_pct") or "nan")))
    return command, seconds, peak, errors


def stats(errors):
    """n, largest, 95th percentile, mean of |e| and count beyond 1 %, of (error, bar) pairs."""
    a = np.abs(np.array([e for e, _ in errors]))
    return len(a), a.max(), np.percentile(a, 95), a.mean(), int((a > 1.0).sum())


def signed_largest(errors):
    """The error of largest magnitude, with its sign."""
    return max((e for e, _ in errors), key=abs)


def covered(errors):
    """"k of n (share %)" of the probes within their bar and the mean bar, or "–"."""
    pairs = [(abs(e), b) for e, b in errors if b == b]
    if not pairs:
        return "–", "–"
    within = sum(e <= b for e, b in pairs)
    mean = sum(b for _, b in pairs) / len(pairs)
    return f"{within} of {len(pairs)} ({100 * within / len(pairs):.0f} %)", f"{mean:.2f} %"


def table(case, setting, path):
    """The markdown table of one setting."""
    command, seconds, peak, errors = load(path)
    everything = [e for v in errors.values() for e in v]
    out = [f"**{case}, {setting}**: `{command}`, {seconds:.1f} s, {peak:.0f} MB\n",
           "| class | probes | largest | 95th pct | mean | beyond 1 % | within the bar | mean bar |",
           "|---|---|---|---|---|---|---|---|"]
    for cls, e in list(errors.items()) + [("all", everything)]:
        n, _, p95, mean, beyond = stats(e)
        within, bar = covered(e)
        out.append(f"| {cls} | {n} | {signed_largest(e):+.2f} % | {p95:.2f} % | {mean:.2f} % | {beyond} | {within} | {bar} |")
    return "\n".join(out) + "\n", (seconds, stats(everything))


def plot(points, path):
    """Largest and 95th-percentile error over all probes against wall time, per case."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for i, (case, runs) in enumerate(points.items()):
        colour = f"C{i}"
        for setting, (seconds, (_, largest, p95, _, _)) in runs:
            ax.scatter(seconds, largest, color=colour, marker="o")
            ax.scatter(seconds, p95, color=colour, marker="x")
            ax.annotate(f"{case}: {setting}", (seconds, largest), fontsize=7, xytext=(4, 2),
                        textcoords="offset points")
    ax.axhline(1.0, color="grey", linestyle="--", linewidth=0.8)
    ax.set(xscale="log", yscale="log", xlabel="wall time of the solve, s (2 loaded cores)",
           ylabel="|error| over all hard probes, %", title="Hard probes: largest (o) and 95th percentile (x)")
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("cases", nargs="+")
    parser.add_argument("--plot", type=Path)
    args = parser.parse_args()
    points = {}
    for case in args.cases:
        for path in sorted(OUT.glob(f"{case}-*.csv")):
            setting = path.stem[len(case) + 1:]
            if setting.endswith("-probes") or not path.read_text().startswith("# "):
                continue
            text, point = table(case, setting, path)
            print(text)
            points.setdefault(case, []).append((setting, point))
    if args.plot:
        plot(points, args.plot)


if __name__ == "__main__":
    main()
