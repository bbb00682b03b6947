"""Compares the ceiling readings of docs/ceiling-study.sh bin by bin (docs/hierarchy.md).

Each 0.25 m ceiling patch is one forward bin and one uniform patch; its four backward
probes and the uniform kernel's four point readings average over it. The sums over the
bins are compared, grouped by the bins' distance from the walls, as illuminance (lx) with
the ceiling's reflectance 0.8. Usage: python3 docs/ceiling-study.py OUT_FOLDER.
"""
import re
import sys

import h5py
import numpy as np

REFLECTANCE = 0.8
out = sys.argv[1]


def field(name):
    f = h5py.File(f"{out}/{name}.h5")
    names = [s.decode() for s in f["/mesh/surface_names"][()]]
    ceiling = np.where(f["/mesh/surface_id"][()] == names.index("ceiling"))[0]
    scale = np.pi / REFLECTANCE
    value = f["/field/luminance"][()].reshape(len(f["/mesh/areas"]), -1)[:, 0] * scale
    error = f["/field/standard_error"][()].reshape(value.shape[0], -1)[:, 0] * scale if "/field/standard_error" in f else None
    return f["/mesh/points"][()][ceiling], value[ceiling], None if error is None else error[ceiling]


def probes(name, columns):
    """The grid of probe readings from a log: illuminance (and its standard error)."""
    grid = np.zeros((64, 48, len(columns)))
    for line in open(f"{out}/{name}.log"):
        m = re.match(r"\s+f (\d+) (\d+)\s+(.*)", line)
        if m:
            numbers = re.findall(r"[-\d.]+(?:e[-+]?\d+)?", m.group(3))
            grid[int(m.group(1)), int(m.group(2))] = [float(numbers[c]) for c in columns]
    return grid


points, forward, forward_error = field("forward")
_, uniform, _ = field("uniform")
backward = probes("backward", [2, 3])
uniform_points = probes("uniform", [1])
rows = []
for (x, _, z), f, fe, e in zip(points, forward, forward_error, uniform):
    a, b = int(x // 0.25), int(z // 0.25)
    block = (slice(2 * a, 2 * a + 2), slice(2 * b, 2 * b + 2))
    b_mean = backward[block][..., 0].mean()
    b_error = np.sqrt((backward[block][..., 1] ** 2).sum()) / 4
    rows.append((b_mean, b_error, f, fe, e, uniform_points[block][..., 0].mean(), min(x, 8 - x, z, 6 - z)))
rows = np.array(rows)
print("ceiling bins by distance from the walls: sums' ratios, % (standard error of backward/forward)")
for low, high in [(0, 0.3), (0.3, 0.6), (0.6, 1.2), (1.2, 9)]:
    r = rows[(rows[:, 6] >= low) & (rows[:, 6] < high)]
    b, f, e, ep = r[:, 0].sum(), r[:, 2].sum(), r[:, 4].sum(), r[:, 5].sum()
    se = np.hypot(np.sqrt((r[:, 1] ** 2).sum()) / b, np.sqrt((r[:, 3] ** 2).sum()) / f)
    print(f"  {low:.1f}-{high:.1f} m ({len(r):3d} bins): backward/forward {100 * (b / f - 1):+.2f} ({100 * se:.2f}), "
          f"uniform/forward {100 * (e / f - 1):+.2f}, uniform's points/its patches {100 * (ep / e - 1):+.2f}")
