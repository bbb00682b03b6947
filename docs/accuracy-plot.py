#!/usr/bin/env python3
"""Plots docs/img/accuracy-vs-time.csv (written by docs/accuracy-study.sh) as an SVG:
the largest probe error (%) against the wall time of `ugo solve` (s), log-log, one
series per kernel (uniform, hierarchical). Standard library only.
docs/office-accuracy.py plots its CSV with it too, with the scene's name as a third argument.

    python3 docs/accuracy-plot.py docs/img/accuracy-vs-time.csv docs/img/accuracy-vs-time.svg [SCENE]
"""
import csv
import math
import sys

W, H = 640, 440
LEFT, RIGHT, TOP, BOTTOM = 70, 20, 40, 60
COLOURS = {"uniform": "#c0392b", "hierarchical": "#2471a3"}


def decades(lo, hi):
    """Powers of ten spanning [lo, hi]."""
    return [10.0**e for e in range(math.floor(math.log10(lo)), math.ceil(math.log10(hi)) + 1)]


def scale(lo, hi, a, b):
    """Maps log10 of a value in [lo, hi] onto [a, b]."""
    span = math.log10(hi) - math.log10(lo)
    return lambda v: a + (b - a) * (math.log10(v) - math.log10(lo)) / span


def label(row):
    if row["method"] == "uniform":
        return f'h {row["patch_size_m"]}'
    return f'{row["link_tolerance"]}, {row["smallest_m"]}'


def axes(x, y, xt, yt):
    out = [f'<rect x="{LEFT}" y="{TOP}" width="{W - LEFT - RIGHT}" height="{H - TOP - BOTTOM}" fill="none" stroke="#000"/>']
    for t in xt:
        out.append(f'<line x1="{x(t):.1f}" y1="{TOP}" x2="{x(t):.1f}" y2="{H - BOTTOM}" stroke="#ddd"/>')
        out.append(f'<text x="{x(t):.1f}" y="{H - BOTTOM + 18}" text-anchor="middle">{t:g}</text>')
    for t in yt:
        out.append(f'<line x1="{LEFT}" y1="{y(t):.1f}" x2="{W - RIGHT}" y2="{y(t):.1f}" stroke="#ddd"/>')
        out.append(f'<text x="{LEFT - 6}" y="{y(t) + 4:.1f}" text-anchor="end">{t:g}</text>')
    out.append(f'<text x="{(LEFT + W - RIGHT) / 2}" y="{H - 15}" text-anchor="middle">wall time of ugo solve, s</text>')
    out.append(f'<text x="18" y="{(TOP + H - BOTTOM) / 2}" text-anchor="middle" '
               f'transform="rotate(-90 18 {(TOP + H - BOTTOM) / 2})">largest probe error, %</text>')
    return out


def main(source, target, scene="Cornell box"):
    rows = list(csv.DictReader(open(source)))
    xs = [float(r["wall_s"]) for r in rows]
    ys = [float(r["max_abs_err_pct"]) for r in rows]
    (x0, x1), (y0, y1) = (min(xs) / 1.3, max(xs) * 1.3), (min(ys) / 1.3, max(ys) * 1.3)
    xt = [t for d in decades(x0, x1) for t in (d, 2 * d, 5 * d) if x0 <= t <= x1]
    yt = [t for d in decades(y0, y1) for t in (d, 2 * d, 5 * d) if y0 <= t <= y1]
    x = scale(x0, x1, LEFT, W - RIGHT)
    y = scale(y0, y1, H - BOTTOM, TOP)
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" font-family="sans-serif" font-size="11">',
           '<rect width="100%" height="100%" fill="#fff"/>',
           f'<text x="{W / 2}" y="22" text-anchor="middle" font-size="14">{scene}: accuracy against time</text>']
    out += axes(x, y, xt, yt)
    for i, (method, colour) in enumerate(COLOURS.items()):
        series = sorted((r for r in rows if r["method"] == method), key=lambda r: float(r["wall_s"]))
        points = " ".join(f'{x(float(r["wall_s"])):.1f},{y(float(r["max_abs_err_pct"])):.1f}' for r in series)
        out.append(f'<polyline points="{points}" fill="none" stroke="{colour}" stroke-width="1.5"/>')
        for r in series:
            px, py = x(float(r["wall_s"])), y(float(r["max_abs_err_pct"]))
            out.append(f'<circle cx="{px:.1f}" cy="{py:.1f}" r="3.5" fill="{colour}" stroke="{colour}"/>')
            out.append(f'<text x="{px + 6:.1f}" y="{py - 5:.1f}" fill="{colour}" font-size="9">{label(r)}</text>')
        out.append(f'<text x="{LEFT + 10}" y="{H - BOTTOM - 30 + 16 * i}" fill="{colour}">{method}</text>')
    out.append("</svg>")
    open(target, "w").write("\n".join(out) + "\n")


if __name__ == "__main__":
    main(*sys.argv[1:4])
