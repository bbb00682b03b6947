#!/usr/bin/env python3
"""Writes ugo's furnished rooms (issue 14, point 5): real scenes for the kernels.

    python3 cases/generate/rooms.py             # write every file below into cases/
    python3 cases/generate/rooms.py --check     # compare the committed files; write nothing
    python3 cases/generate/rooms.py --out DIR   # write into DIR instead of cases/
    python3 cases/generate/rooms.py --detail 2  # the seats' OBJ with 4x the triangles

Files (relative to cases/):

    office.toml            a furnished 8 x 6 x 2.8 m office, about 1,000 quads
    office-downlight.ies   its recessed downlight: batwing, 3,400 lm (LM-63-2002, type C)
    lecture-hall.toml      a tiered lecture hall with 140 box seats, about 3,000 quads
    seat-room.toml         two of its tiers, four seats a row, in a 3 x 4.5 m room
    hall-obj.toml          the same hall whose seat cushions are triangle meshes ...
    hall-obj/seats.obj     ... about 2e5 triangles (not committed: `make cases` writes it)
    hall-downlight.ies     the halls' downlight: cos^2, 6,000 lm (LM-63-2002, type C)

Standard library only, deterministic (fixed seeds, fixed number formats): running it
again rewrites the committed files byte for byte. Lengths are metres, y is up.
"""

import argparse
import math
import os
import random
import sys

COMMAND = "python3 cases/generate/rooms.py"
HERE = os.path.dirname(os.path.abspath(__file__))
CASES = os.path.dirname(HERE)
# Files the script writes but git does not hold (too large); `--check` skips them.
GENERATED_ONLY = ["hall-obj/seats.obj"]


# ----------------------------------------------------------------------------- numbers


def num(x, digits=4):
    """A number as TOML text: fixed decimals, trailing zeros dropped, no '-0'."""
    text = f"{x:.{digits}f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


def vec(v, digits=4):
    return "[" + ", ".join(num(c, digits) for c in v) + "]"


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def turn_y(x, z, degrees):
    """(x, z) turned about the vertical axis as ugo's `rotate_y_deg` turns a box
    (glam's rotation about y: +x goes towards -z for a positive angle)."""
    a = math.radians(degrees)
    return x * math.cos(a) + z * math.sin(a), -x * math.sin(a) + z * math.cos(a)


def facing(dx, dz):
    """The `rotate_y_deg` that turns a piece facing +z (local) to face (dx, dz)."""
    return math.degrees(math.atan2(dx, dz))


# ----------------------------------------------------------------------------- a case


class Case:
    """A case file being written: its tables in order, and the quads they hold."""

    def __init__(self, name, description, header, patch_size, tolerance=1e-6, hierarchy=None, command=COMMAND):
        """`hierarchy = (link tolerance, root size)` selects the hierarchical kernel, whose
        leaves split down to `patch_size`; `command` is the script named in the header."""
        self.header, self.command = header, command
        self.lines = [
            "[scene]",
            f'name = "{name}"',
            f'description = "{description}"',
            "",
            "[discretization]",
            f"patch_size = {num(patch_size)}",
        ] + ([
            'kernel = "hierarchical"',
            f"root_size = {num(hierarchy[1])}",
            f"link_tolerance = {hierarchy[0]:g}".replace("e-0", "e-"),
        ] if hierarchy else []) + [
            "",
            "[solver]",
            f"tolerance = {tolerance:g}".replace("e-0", "e-"),
        ]
        self.materials, self.surfaces, self.luminaires, self.light_scenes = [], [], [], []
        self.probes, self.observers, self.grids, self.cameras = [], [], [], []
        self.quads = 0  # a rectangle is 1 quad, a box 6
        self.boxes = []  # (name, min, max, rotate_y_deg), for `overlaps`
        self.triangles = 0  # in OBJ files

    def material(self, name, reflectance):
        self.materials += ["[[material]]", f'name = "{name}"', 'type = "lambert"',
                           f"reflectance = {num(reflectance, 3)}", ""]

    def comment(self, text):
        self.surfaces += [f"# {text}", ""]

    def rect(self, name, material, origin, u, v, front):
        """The parallelogram origin + s u + t v, its front towards `front`."""
        if dot(cross(u, v), front) < 0:
            u, v = v, u
        self.surfaces += ["[[surface]]", f'name = "{name}"', 'shape = "rectangle"',
                          f'material = "{material}"', f"origin = {vec(origin)}",
                          f"edge_u = {vec(u)}", f"edge_v = {vec(v)}", ""]
        self.quads += 1

    def box(self, name, material, lo, hi, rotate=0.0):
        rows = ["[[surface]]", f'name = "{name}"', 'shape = "box"', f'material = "{material}"',
                f"min = {vec(lo)}", f"max = {vec(hi)}"]
        if num(rotate, 2) != "0":
            rows.append(f"rotate_y_deg = {num(rotate, 2)}")
        self.surfaces += rows + [""]
        self.quads += 6
        self.boxes.append((name, lo, hi, rotate))

    def mesh(self, name, material, file, triangles):
        self.surfaces += ["[[surface]]", f'name = "{name}"', 'shape = "mesh"',
                          f'material = "{material}"', f'file = "{file}"', ""]
        self.triangles += triangles

    def luminaire(self, name, file, position, aim=None, group=None):
        rows = ["[[luminaire]]", f'name = "{name}"', 'type = "ies"', f'file = "{file}"',
                f"position = {vec(position)}"]
        if aim is not None:
            rows.append(f"aim = {vec(aim)}")
        if group is not None:
            rows.append(f'group = "{group}"')
        self.luminaires += rows + [""]

    def light_scene(self, name, factors):
        """A light scene: a factor (or true/false) per group of luminaires."""
        show = {True: "true", False: "false"}
        levels = ", ".join(f"{g} = {show[f] if isinstance(f, bool) else num(f, 2)}" for g, f in factors)
        self.light_scenes += ["[[light_scene]]", f'name = "{name}"', f"groups = {{ {levels} }}", ""]

    def probe(self, name, position, normal):
        self.probes += ["[[probe]]", f'name = "{name}"', f"position = {vec(position)}",
                        f"normal = {vec(normal)}", ""]

    def observer(self, name, position, look, ugr_limit):
        self.observers += ["[[observer]]", f'name = "{name}"', f"position = {vec(position)}",
                           f"look = {vec(look)}", f"ugr_limit = {num(ugr_limit, 0)}", ""]

    def grid(self, name, origin, u, v, resolution, normal):
        if dot(cross(u, v), normal) < 0:
            u, v, resolution = v, u, resolution[::-1]
        self.grids += ["[[grid]]", f'name = "{name}"', f"origin = {vec(origin)}",
                       f"edge_u = {vec(u)}", f"edge_v = {vec(v)}",
                       f"resolution = [{resolution[0]}, {resolution[1]}]", f"normal = {vec(normal)}", ""]

    def camera(self, name, position, look_at, fov, resolution):
        self.cameras += ["[[camera]]", f'name = "{name}"', f"position = {vec(position)}",
                         f"look_at = {vec(look_at)}", f"fov_deg = {num(fov, 1)}",
                         f"resolution = [{resolution[0]}, {resolution[1]}]", ""]

    def text(self):
        counts = f"{self.quads:,} quads" + (f" and {self.triangles:,} OBJ triangles" if self.triangles else "")
        head = [f"# {line}".rstrip() for line in self.header]
        head += ["#", f"# Generated by `{self.command}` (do not edit: edit the script and rerun it).",
                 f"# {counts} (a box is 6 quads).", ""]
        body = self.lines + [""] + self.materials + self.surfaces + self.luminaires + self.light_scenes
        body += self.probes + self.observers + self.grids + self.cameras
        return "\n".join(head + body).rstrip("\n") + "\n"


class Group:
    """A piece of furniture placed rigidly: parts given in local coordinates about a
    local origin put at `at`, the whole turned by `angle` degrees about the vertical.
    Each part is a box turned by the same angle about its own (moved) centre, which is
    exactly the rigid turn of the piece."""

    def __init__(self, case, name, at, angle=0.0):
        self.case, self.name, self.at, self.angle = case, name, at, angle

    def box(self, part, material, lo, hi):
        cx, cz = turn_y((lo[0] + hi[0]) / 2, (lo[2] + hi[2]) / 2, self.angle)
        half = [(h - l) / 2 for l, h in zip(lo, hi)]
        centre = (self.at[0] + cx, self.at[1] + (lo[1] + hi[1]) / 2, self.at[2] + cz)
        self.case.box(f"{self.name}, {part}", material,
                      [c - h for c, h in zip(centre, half)], [c + h for c, h in zip(centre, half)], self.angle)


def room_shell(case, size, materials):
    """The six inward-facing rectangles of a size[0] x size[1] x size[2] room at the origin."""
    w, h, d = size
    floor, ceiling, wall = materials
    case.rect("floor", floor, (0, 0, 0), (w, 0, 0), (0, 0, d), (0, 1, 0))
    case.rect("ceiling", ceiling, (0, h, 0), (w, 0, 0), (0, 0, d), (0, -1, 0))
    case.rect("wall x = 0", wall, (0, 0, 0), (0, h, 0), (0, 0, d), (1, 0, 0))
    case.rect(f"wall x = {num(w)}", wall, (w, 0, 0), (0, h, 0), (0, 0, d), (-1, 0, 0))
    case.rect("wall z = 0", wall, (0, 0, 0), (w, 0, 0), (0, h, 0), (0, 0, 1))
    case.rect(f"wall z = {num(d)}", wall, (0, 0, d), (w, 0, 0), (0, h, 0), (0, 0, -1))


def overlaps(case, tolerance=1e-4):
    """Pairs of boxes of `case` that interpenetrate by more than `tolerance` (touching is
    fine): separating axes of the turned rectangles in plan, and their heights."""

    def plan(lo, hi, rotate):
        centre = ((lo[0] + hi[0]) / 2, (lo[2] + hi[2]) / 2)
        axes = [turn_y(1, 0, rotate), turn_y(0, 1, rotate)]
        return centre, ((hi[0] - lo[0]) / 2, (hi[2] - lo[2]) / 2), axes

    def apart(a, b):
        (ca, ha, xa), (cb, hb, xb) = a, b
        for n in xa + xb:
            reach = sum(h * abs(dot(x, n)) for h, x in zip(ha, xa)) + sum(h * abs(dot(x, n)) for h, x in zip(hb, xb))
            if abs(dot((cb[0] - ca[0], cb[1] - ca[1]), n)) >= reach - tolerance:
                return True
        return False

    boxes = [(name, lo[1], hi[1], plan(lo, hi, rotate)) for name, lo, hi, rotate in case.boxes]
    found = []
    for i, (name_a, y0a, y1a, pa) in enumerate(boxes):
        for name_b, y0b, y1b, pb in boxes[i + 1:]:
            if min(y1a, y1b) - max(y0a, y0b) > tolerance and not apart(pa, pb):
                found.append((name_a, name_b))
    return found


# ----------------------------------------------------------------------------- IES files


def ies_flux(c_angles, gammas, table, quadrant):
    """The exact flux of the table's bilinear interpolant, as ugo integrates it: closed-
    form weights in gamma, trapezoids in C (over the quadrant, times 4; or axial)."""

    def column(values):
        total = 0.0
        for i in range(len(gammas) - 1):
            t0, t1 = math.radians(gammas[i]), math.radians(gammas[i + 1])
            h, s = t1 - t0, math.sin(t1) - math.sin(t0)
            total += values[i] * (math.cos(t0) - s / h) + values[i + 1] * (s / h - math.cos(t1))
        return total

    columns = [column(values) for values in table]
    if not quadrant:
        return 2 * math.pi * columns[0]
    pairs = zip(c_angles, c_angles[1:], columns, columns[1:])
    return 4 * sum(math.radians(c1 - c0) * (j0 + j1) / 2 for c0, c1, j0, j1 in pairs)


def ies_text(title, lamp_lumens, lor, watts, size, c_angles, shape):
    """An LM-63-2002 type C file whose distribution emits lor x lamp_lumens (relative
    photometry: candela for the rated lamp). `shape(C, gamma)` in degrees gives the form."""
    gammas = list(range(0, 91, 5))
    raw = [[shape(c, g) for g in gammas] for c in c_angles]
    scale = lor * lamp_lumens / ies_flux(c_angles, gammas, raw, len(c_angles) > 1)
    table = [[round(v * scale, 1) for v in column] for column in raw]

    def wrapped(values, per_line=10):
        return [" ".join(values[i:i + per_line]) for i in range(0, len(values), per_line)]

    lines = ["IESNA:LM-63-2002", "[TEST] synthetic", "[TESTLAB] ugo",
             f"[ISSUEDATE] generated by {COMMAND}",
             "[MANUFAC] none (a synthetic distribution for ugo's furnished cases)",
             f"[LUMINAIRE] {title}",
             f"[OTHER] light output ratio {lor}: the distribution emits {num(lor * lamp_lumens, 1)} lm",
             "TILT=NONE",
             f"1 {lamp_lumens} 1 {len(gammas)} {len(c_angles)} 1 2 {num(size[0])} {num(size[1])} 0",
             f"1 1 {watts}"]
    lines += wrapped([num(g, 1) for g in gammas]) + wrapped([num(c, 1) for c in c_angles])
    for column in table:
        lines += wrapped([num(v, 1) for v in column])
    return "\n".join(lines) + "\n"


def office_downlight():
    """A recessed 600 x 600 batwing panel: peak near 40 deg, a little narrower across (C90)."""

    def shape(c, g):
        s = math.sin(math.radians(g))
        return math.cos(math.radians(g)) * (1 + 1.5 * s * s) * (1 - 0.15 * math.sin(math.radians(c)) ** 2 * s * s)

    return ies_text("recessed batwing panel 600 x 600, quadrant symmetric", 4000, 0.85, 32,
                    (0.6, 0.6), [0, 22.5, 45, 67.5, 90], shape)


def hall_downlight():
    """A round high-ceiling downlight, I ~ cos^2(gamma), axially symmetric."""
    return ies_text("round downlight, cos^2 distribution, axial", 7500, 0.8, 55, (0.25, 0.25), [0],
                    lambda c, g: math.cos(math.radians(g)) ** 2)


# ----------------------------------------------------------------------------- the office

OFFICE = (8.0, 2.8, 6.0)  # width (x), height (y), depth (z)
DESK_TOP = 0.74  # height of a desk's top face, m


def desk(case, name, at, angle=0.0):
    """A 1.6 x 0.8 m desk on four legs with a modesty panel at the back (local -z: the
    user sits at +z and faces -z) and a monitor: 8 boxes."""
    g = Group(case, name, at, angle)
    g.box("top", "desk", (-0.8, DESK_TOP - 0.025, -0.4), (0.8, DESK_TOP, 0.4))
    for i, (x, z) in enumerate([(-0.75, -0.35), (0.75, -0.35), (-0.75, 0.35), (0.75, 0.35)]):
        g.box(f"leg {i + 1}", "metal", (x - 0.025, 0, z - 0.025), (x + 0.025, DESK_TOP - 0.025, z + 0.025))
    g.box("modesty panel", "metal", (-0.725, 0.3, -0.37), (0.725, DESK_TOP - 0.025, -0.35))
    g.box("monitor", "monitor", (-0.28, DESK_TOP + 0.16, -0.2), (0.28, DESK_TOP + 0.49, -0.17))
    g.box("monitor stand", "metal", (-0.1, DESK_TOP, -0.27), (0.1, DESK_TOP + 0.16, -0.13))


def office_chair(case, name, at, angle):
    """A swivel chair facing local +z: seat, back, back post, column, round-ish base."""
    g = Group(case, name, at, angle)
    g.box("base", "metal", (-0.28, 0, -0.28), (0.28, 0.04, 0.28))
    g.box("column", "metal", (-0.03, 0.04, -0.03), (0.03, 0.42, 0.03))
    g.box("seat", "fabric", (-0.23, 0.42, -0.22), (0.23, 0.49, 0.22))
    g.box("back post", "metal", (-0.03, 0.49, -0.25), (0.03, 0.58, -0.22))
    g.box("back", "fabric", (-0.22, 0.58, -0.27), (0.22, 1.0, -0.22))


def meeting_chair(case, name, at, angle):
    """A four-legged chair facing local +z, the back resting on the seat's rear edge."""
    g = Group(case, name, at, angle)
    for i, (x, z) in enumerate([(-0.19, -0.19), (0.19, -0.19), (-0.19, 0.19), (0.19, 0.19)]):
        g.box(f"leg {i + 1}", "metal", (x - 0.015, 0, z - 0.015), (x + 0.015, 0.43, z + 0.015))
    g.box("seat", "fabric", (-0.22, 0.43, -0.22), (0.22, 0.47, 0.22))
    g.box("back", "fabric", (-0.21, 0.47, -0.22), (0.21, 0.88, -0.19))


def armchair(case, name, at, angle):
    """A lounge armchair facing local +z: base, back and two arms."""
    g = Group(case, name, at, angle)
    g.box("base", "fabric", (-0.4, 0, -0.4), (0.4, 0.4, 0.4))
    g.box("back", "fabric", (-0.4, 0.4, -0.4), (0.4, 0.8, -0.25))
    g.box("left arm", "fabric", (-0.4, 0.4, -0.25), (-0.28, 0.6, 0.4))
    g.box("right arm", "fabric", (0.28, 0.4, -0.25), (0.4, 0.6, 0.4))


def bookshelf(case, rng, x_wall, z0, z1):
    """A 2 m bookshelf against the wall x = x_wall (its back), from z0 to z1: nine
    boards and dozens of books of random size and shade, pushed to the back."""
    depth, board = 0.35, 0.02
    x0 = x_wall - depth
    g = Group(case, "bookshelf", (0, 0, 0))
    g.box("back", "wood", (x_wall - board, 0, z0), (x_wall, 2.0, z1))
    g.box("left side", "wood", (x0, 0, z0), (x_wall - board, 2.0, z0 + board))
    g.box("right side", "wood", (x0, 0, z1 - board), (x_wall - board, 2.0, z1))
    levels = [0.0, 0.4, 0.8, 1.2, 1.6, 1.98]
    for i, y in enumerate(levels):
        g.box(f"board {i + 1}", "wood", (x0, y, z0 + board), (x_wall - board, y + board, z1 - board))
    count = 0
    for shelf, y in enumerate(levels[:-1]):
        z = z0 + board + rng.uniform(0.02, 0.3)
        for _ in range(rng.randint(6, 9)):
            width, height, d = rng.uniform(0.02, 0.06), rng.uniform(0.18, 0.32), rng.uniform(0.14, 0.24)
            if z + width > z1 - board - 0.01:
                break
            count += 1
            shade = rng.randrange(len(BOOKS))
            g.box(f"book {count}", f"book {shade + 1}", (x_wall - board - d, y + board, z),
                  (x_wall - board, y + board + height, z + width))
            z += width + rng.choice([0.0, 0.002, 0.005, 0.005, 0.01, 0.12])
    return count


BOOKS = [0.08, 0.15, 0.25, 0.35, 0.5, 0.65]  # reflectances of the books' covers


def office():
    w, h, d = OFFICE
    rng = random.Random(14)
    case = Case("office", "Furnished 8 x 6 x 2.8 m office, 12 recessed batwing downlights of 3,400 lm",
                ["A furnished open-plan office, 8 x 6 x 2.8 m, closed (no windows): six desks with",
                 "monitors and swivel chairs (four in a cluster split by a screen, two against the wall",
                 "z = 6), a meeting table with four chairs before a whiteboard, a lounge corner with two",
                 "turned armchairs, a bookshelf with dozens of books, cabinets, a free-standing partition",
                 "and a door. Twelve recessed batwing downlights (office-downlight.ies, 3,400 lm each)",
                 "1 cm below the ceiling. Reflectances: floor 0.2, ceiling 0.8, walls 0.6, furniture",
                 "0.05 to 0.8. Probes on the desks and walls, an observer's UGR at desk 1, a work",
                 "plane at 0.75 m (its points inside furniture are left out of its statistics, with a",
                 "warning), one camera.",
                 "Solved with the hierarchical kernel (roots of 1 m, links to 1e-2, elements down to",
                 "0.125 m: every probe within 0.9 % of Monte Carlo, docs/hierarchy.md); the uniform",
                 "kernel is one option away: --kernel uniform --patch-size 0.25 (slow).",
                 "Two groups of six downlights, \"meeting\" (x = 1 and 3 m: the meeting table and",
                 "the lounge) and \"desks\" (x = 5 and 7 m), and two light scenes that dim them:",
                 "ugo render out/office.h5 --light-scene evening draws one."],
                patch_size=0.15, hierarchy=(1e-2, 1.0))
    for name, rho in [("floor", 0.2), ("ceiling", 0.8), ("wall", 0.6), ("desk", 0.5), ("metal", 0.35),
                      ("monitor", 0.05), ("fabric", 0.12), ("cabinet", 0.7), ("wood", 0.4),
                      ("whiteboard", 0.8), ("partition", 0.3), ("door", 0.35)]:
        case.material(name, rho)
    for i, rho in enumerate(BOOKS):
        case.material(f"book {i + 1}", rho)

    case.comment("The room: inward-facing floor, ceiling and walls.")
    room_shell(case, (w, h, d), ("floor", "ceiling", "wall"))

    case.comment("Workstations: a cluster of four desks split by a desk screen, two against the wall z = 6.")
    desks = [("desk 1", (4.4, 0, 2.0), 180), ("desk 2", (6.0, 0, 2.0), 180),
             ("desk 3", (4.4, 0, 2.84), 0), ("desk 4", (6.0, 0, 2.84), 0),
             ("desk 5", (4.4, 0, 5.58), 180), ("desk 6", (6.2, 0, 5.58), 180)]
    for name, at, angle in desks:
        desk(case, name, at, angle)
    Group(case, "desk screen", (5.2, 0, 2.42)).box("panel", "partition", (-1.6, DESK_TOP, -0.02),
                                                   (1.6, 1.2, 0.02))
    for i, (name, (x, _, z), angle) in enumerate(desks):
        away = 0.65 if angle == 0 else -0.65  # the user sits on the desk's local +z side
        office_chair(case, f"chair {i + 1}", (x + rng.uniform(-0.15, 0.15), 0, z + away),
                     angle + 180 + rng.uniform(-25, 25))

    case.comment("Meeting: a table before the whiteboard on the wall x = 0, four chairs turned to it.")
    table = Group(case, "meeting table", (1.8, 0, 3.0))
    table.box("top", "desk", (-0.5, 0.72, -1.0), (0.5, 0.75, 1.0))
    table.box("leg 1", "metal", (-0.3, 0, -0.8), (0.3, 0.72, -0.76))
    table.box("leg 2", "metal", (-0.3, 0, 0.76), (0.3, 0.72, 0.8))
    for i, (x, z, towards) in enumerate([(1.0, 2.5, 1), (1.0, 3.5, 1), (2.6, 2.5, -1), (2.6, 3.5, -1)]):
        meeting_chair(case, f"meeting chair {i + 1}", (x, 0, z), facing(towards, 0) + rng.uniform(-12, 12))
    case.box("whiteboard", "whiteboard", (0, 0.9, 2.0), (0.02, 2.1, 4.0))

    case.comment("Lounge corner: a coffee table and two armchairs, turned.")
    coffee = Group(case, "coffee table", (1.5, 0, 5.0), 30)
    coffee.box("top", "wood", (-0.4, 0.4, -0.3), (0.4, 0.44, 0.3))
    coffee.box("base", "metal", (-0.25, 0, -0.15), (0.25, 0.4, 0.15))
    for i, (x, z) in enumerate([(0.7, 4.5), (2.3, 5.5)]):
        armchair(case, f"armchair {i + 1}", (x, 0, z), facing(1.5 - x, 5.0 - z))

    case.comment("Storage: a bookshelf on the wall x = 8, cabinets on the wall z = 0, a partition.")
    books = bookshelf(case, rng, w, 1.0, 3.0)
    for i, x in enumerate([3.6, 4.4, 5.2]):
        g = Group(case, f"cabinet {i + 1}", (x + 0.4, 0, 0.225))
        g.box("carcass", "cabinet", (-0.4, 0.0, -0.225), (0.4, 0.7, 0.225))
        g.box("top", "wood", (-0.4, 0.7, -0.225), (0.4, 0.72, 0.225))
    tall = Group(case, "tall cabinet", (7.6, 0, 0.25))
    tall.box("plinth", "metal", (-0.38, 0, -0.23), (0.38, 0.08, 0.23))
    tall.box("carcass", "cabinet", (-0.4, 0.08, -0.25), (0.4, 2.0, 0.25))
    part = Group(case, "partition", (3.15, 0, 4.9), 80)
    part.box("panel", "partition", (-0.9, 0.05, -0.025), (0.9, 1.6, 0.025))
    part.box("foot 1", "metal", (-0.8, 0, -0.2), (-0.74, 0.05, 0.2))
    part.box("foot 2", "metal", (0.74, 0, -0.2), (0.8, 0.05, 0.2))
    case.box("door", "door", (w - 0.03, 0, 4.0), (w, 2.1, 4.9))

    for i, (x, z) in enumerate((x, z) for z in (1.0, 3.0, 5.0) for x in (1.0, 3.0, 5.0, 7.0)):
        group = "meeting" if x < 4 else "desks"
        case.luminaire(f"downlight {i + 1}", "office-downlight.ies", (x, h - 0.01, z), group=group)
    case.light_scene("meeting", [("meeting", 1.0), ("desks", 0.2)])
    case.light_scene("evening", [("meeting", False), ("desks", 0.5)])

    for name, (x, _, z), angle in desks:
        case.probe(f"{name}, top", (x, DESK_TOP, z), (0, 1, 0))
    case.probe("whiteboard, centre", (0.02, 1.5, 3.0), (1, 0, 0))
    case.probe("wall z = 0, above the cabinets", (2.0, 1.5, 0), (0, 0, 1))
    case.probe("wall x = 8, by the door", (w, 1.5, 3.5), (-1, 0, 0))
    case.probe("wall z = 6, behind the lounge", (2.0, 1.5, d), (0, 0, -1))
    case.probe("floor, open", (3.0, 0, 3.3), (0, 1, 0))
    case.probe("ceiling, centre", (4.0, h, 3.0), (0, -1, 0))
    # The UGR (CIE 117) of someone seated at desk 1 looking along the room; EN 12464-1
    # asks UGR_L 19 for writing and reading.
    case.observer("seated at desk 1", (4.4, 1.2, 1.2), (0, 0, 1), 19)
    # 0.5 m spacing: every grid point costs a gather over all patches. Points that fall
    # inside a chair back, a screen or the partition are left out of E_avg, E_min and U0
    # (readout::obstructed; the one in the partition's panel, with a warning).
    case.grid("work plane", (0.5, 0.75, 0.5), (0, 0, d - 1.0), (w - 1.0, 0, 0), (10, 14), (0, 1, 0))
    case.camera("room", (7.7, 1.65, 5.75), (2.0, 0.6, 1.6), 72, (800, 600))
    return case, books


# ----------------------------------------------------------------------------- the lecture hall

HALL = (12.0, 6.5, 16.0)  # width (x), height (y), depth (z); the board on the wall z = 0
ROWS, RISER, TREAD, FRONT = 10, 0.3, 1.0, 4.5  # tiers: count, rise, depth; the flat front's depth
SEATS, PITCH, AISLE = 7, 0.6, 1.2  # seats per block (two blocks a row), their pitch, the centre aisle


def tier(k, front=FRONT):
    """Row k (1, 2, ...) behind a flat front `front` deep: the height of its tread and the z
    where it starts."""
    return k * RISER, front + (k - 1) * TREAD


def hall_shell(case):
    """The lecture hall's closed shell (`tiered_shell`)."""
    tiered_shell(case, HALL, ROWS, FRONT)


def tiered_shell(case, size, rows, front):
    """A closed tiered room of `size`: the flat front `front` deep, a riser and a tread per
    row (the last tread runs to the back wall), the ceiling, front and back walls, and each
    side wall as one rectangle per tier (above that tier's tread)."""
    w, h, d = size
    case.rect("front floor", "floor", (0, 0, 0), (w, 0, 0), (0, 0, front), (0, 1, 0))
    edges = [0.0] + [tier(k, front)[1] for k in range(1, rows + 1)] + [d]
    for k in range(1, rows + 1):
        y, z = tier(k, front)
        case.rect(f"riser {k}", "floor", (0, y - RISER, z), (w, 0, 0), (0, RISER, 0), (0, 0, -1))
        case.rect(f"tread {k}", "floor", (0, y, z), (w, 0, 0), (0, 0, edges[k + 1] - z), (0, 1, 0))
    case.rect("ceiling", "ceiling", (0, h, 0), (w, 0, 0), (0, 0, d), (0, -1, 0))
    case.rect("front wall", "wall", (0, 0, 0), (w, 0, 0), (0, h, 0), (0, 0, 1))
    top = tier(rows, front)[0]
    case.rect("back wall", "wall", (0, top, d), (w, 0, 0), (0, h - top, 0), (0, 0, -1))
    for k in range(rows + 1):
        y, z0, z1 = k * RISER, edges[k], edges[k + 1]
        case.rect(f"left wall, tier {k}", "wall", (0, y, z0), (0, h - y, 0), (0, 0, z1 - z0), (1, 0, 0))
        case.rect(f"right wall, tier {k}", "wall", (w, y, z0), (0, h - y, 0), (0, 0, z1 - z0), (-1, 0, 0))


def blocks():
    """The x where each block of seats starts (its first armrest's centre)."""
    width = SEATS * PITCH
    return [HALL[0] / 2 - AISLE / 2 - width, HALL[0] / 2 + AISLE / 2]


def seat_x(x0, i):
    """The x range of seat i of the block starting at x0 (between its armrests)."""
    return x0 + i * PITCH + 0.025, x0 + (i + 1) * PITCH - 0.025


def hall_rows(case, seats):
    """Per row and block: a writing desk (top and front panel), armrests, and the seats
    made by `seats(case, name, x0, x1, y, z)` (boxes or a mesh)."""
    for k in range(1, ROWS + 1):
        y, z = tier(k)
        for b, x0 in enumerate(blocks()):
            seat_block(case, f"row {k} {'left' if b == 0 else 'right'}", x0, SEATS, y, z, seats)


def seat_block(case, row, x0, count, y, z, seats):
    """One block of a row on the tread at height `y` starting at `z`: a writing desk (top
    and front panel), `count + 1` armrests from `x0` on, and `count` seats made by
    `seats(case, name, x0, x1, y, z)`."""
    x1 = x0 + count * PITCH
    case.box(f"{row}, desk", "desk", (x0 - 0.025, y + 0.72, z + 0.03), (x1 + 0.025, y + 0.75, z + 0.38))
    case.box(f"{row}, desk panel", "wood", (x0 - 0.025, y, z + 0.03), (x1 + 0.025, y + 0.72, z + 0.06))
    for a in range(count + 1):
        xa = x0 + a * PITCH
        case.box(f"{row}, armrest {a + 1}", "wood", (xa - 0.025, y, z + 0.48), (xa + 0.025, y + 0.65, z + 0.92))
    for i in range(count):
        seats(case, f"{row}, seat {i + 1}", *seat_x(x0, i), y, z)


def box_seat(case, name, x0, x1, y, z):
    case.box(f"{name}, pan", "seat", (x0, y + 0.4, z + 0.5), (x1, y + 0.46, z + 0.9))
    case.box(f"{name}, back", "seat", (x0, y + 0.46, z + 0.9), (x1, y + 1.0, z + 0.95))


def hall_front(case):
    """The lecturer's end: a board with its chalk tray, a demonstration bench, a lectern, doors."""
    w, h, d = HALL
    case.box("board", "board", (3.0, 1.0, 0), (9.0, 2.5, 0.03))
    case.box("board tray", "metal", (3.0, 0.95, 0), (9.0, 1.0, 0.08))
    bench = Group(case, "bench", (6.0, 0, 2.4))
    bench.box("top", "desk", (-2.0, 0.88, -0.4), (2.0, 0.92, 0.4))
    bench.box("left end", "wood", (-2.0, 0, -0.4), (-1.96, 0.88, 0.4))
    bench.box("right end", "wood", (1.96, 0, -0.4), (2.0, 0.88, 0.4))
    lectern = Group(case, "lectern", (9.3, 0, 2.0), -25)
    lectern.box("body", "wood", (-0.3, 0, -0.25), (0.3, 1.05, 0.25))
    lectern.box("top", "desk", (-0.35, 1.05, -0.3), (0.35, 1.09, 0.3))
    case.box("door left", "door", (0, 0, 1.2), (0.03, 2.2, 2.4))
    case.box("door right", "door", (w - 0.03, 0, 1.2), (w, 2.2, 2.4))


def hall_lights_and_readings(case):
    """30 downlights, two aimed at the board; probes on board, lectern, desks; a grid on
    the board and one along the desks of every third row (kept small: every grid point
    costs a gather over all patches); a camera from the back."""
    w, h, d = HALL
    xs, zs = [1.2 + 2.4 * i for i in range(5)], [1.6 + 2.7 * j for j in range(6)]
    for i, (x, z) in enumerate((x, z) for z in zs for x in xs):
        case.luminaire(f"downlight {i + 1}", "hall-downlight.ies", (x, h - 0.01, z))
    for i, x in enumerate((4.5, 7.5)):
        case.luminaire(f"board light {i + 1}", "hall-downlight.ies", (x, h - 0.01, 2.6), (0, 1.75 - h, -2.6))
    case.probe("board, centre", (6.0, 1.75, 0.03), (0, 0, 1))
    case.probe("lectern, top", (9.3, 1.09, 2.0), (0, 1, 0))
    case.probe("bench, top", (6.0, 0.92, 2.4), (0, 1, 0))
    case.probe("front floor, centre", (6.0, 0, 3.5), (0, 1, 0))
    for k in (1, 5, 10):
        y, z = tier(k)
        for b, x0 in enumerate(blocks()):
            x = x0 + SEATS * PITCH / 2
            case.probe(f"row {k} {'left' if b == 0 else 'right'}, desk", (x, y + 0.75, z + 0.2), (0, 1, 0))
    case.probe("back wall, eye height", (6.0, tier(ROWS)[0] + 1.6, d), (0, 0, -1))
    case.grid("board", (3.0, 1.0, 0.04), (6.0, 0, 0), (0, 1.5, 0), (12, 3), (0, 0, 1))
    for k in (1, 4, 7, 10):
        y, z = tier(k)
        x0, x1 = blocks()[0], blocks()[1] + SEATS * PITCH
        case.grid(f"desks row {k}", (x0, y + 0.76, z + 0.08), (x1 - x0, 0, 0), (0, 0, 0.25), (24, 1), (0, 1, 0))
    case.camera("from the back", (6.0, tier(ROWS)[0] + 1.7, d - 0.6), (6.0, 1.4, 0), 62, (800, 500))


def hall_case(name, description, header, seats, materials, patch_size=0.5, hierarchy=None):
    case = Case(name, description, header, patch_size=patch_size, hierarchy=hierarchy)
    for material, rho in [("floor", 0.25), ("ceiling", 0.75), ("wall", 0.55), ("desk", 0.5), ("wood", 0.35),
                          ("metal", 0.4), ("board", 0.12), ("door", 0.35)] + materials:
        case.material(material, rho)
    case.comment("The hall: flat front, ten tiers, walls and ceiling (closed).")
    hall_shell(case)
    case.comment("The front: board, bench, lectern, doors.")
    hall_front(case)
    case.comment("Ten rows in two blocks of seven seats, a desk before each block.")
    hall_rows(case, seats)
    hall_lights_and_readings(case)
    return case


HALL_HEADER = [
    "A lecture hall, 12 x 16 m, 6.5 m high at the front: a flat front 4.5 m deep with a board",
    "(6 x 1.5 m), a demonstration bench and a turned lectern, then ten tiers (0.3 m rise, 1 m",
    "tread), each with two blocks of seven seats behind a writing desk, a centre aisle of",
    "1.2 m. 30 downlights of 6,000 lm (hall-downlight.ies) 1 cm below the ceiling, two more",
    "aimed at the board. Reflectances: floor 0.25, ceiling 0.75, walls 0.55, board 0.12.",
    "Probes on the board, lectern and desks; grids on the board and along the desks of",
    "rows 1, 4, 7 and 10 (grid points over the aisles are in the air at desk height).",
]


def lecture_hall():
    header = HALL_HEADER + [
        "Seats are boxes (pan and back). Solved with the hierarchical kernel: roots of 1 m, link",
        "tolerance 3e-2, leaves down to 0.25 m (docs/hierarchy.md: every probe within 0.9 %",
        "of `ugo trace` in 37 s; the uniform kernel at 0.5 m: within 0.5 % in 152 s, 2x the",
        "memory; `--link-tolerance 1e-2`: within 0.6 %)."]
    return hall_case("lecture hall", "Tiered lecture hall, 140 box seats, 32 downlights of 6,000 lm", header,
                     box_seat, [("seat", 0.15)], patch_size=0.25, hierarchy=(3e-2, 1.0))


SEAT_ROOM = (3.0, 3.5, 4.5)  # width (x), height (y), depth (z) of the seat room


def seat_room():
    """Two of the lecture hall's tiers in a small closed room (issue 34, docs/accuracy.md,
    "Seats on tiers"): its undersides and umbrae read dark, its ceiling corners bright, in
    seconds instead of the hall's minutes."""
    w, h, d = SEAT_ROOM
    header = [
        "Two of the lecture hall's tiers in a 3 x 4.5 x 3.5 m closed room (issue 34,",
        "docs/accuracy.md, \"Seats on tiers\"): a flat front 1.5 m deep, then two tiers (0.3 m",
        "rise, 1 m tread; the second runs to the back wall), each with the hall's writing desk",
        "and four of its box seats between armrests; four of its 6,000 lm downlights 1 cm below",
        "the ceiling; its reflectances and settings (roots of 1 m, link tolerance 3e-2, leaves",
        "down to 0.25 m). The hall's undersides (down to -5.2 %) and umbrae (-4.5 %) read dark",
        "and its ceiling corners bright against `ugo trace`; so do this room's hard probes",
        "(tests/data/accuracy/seat-room.csv), in 5 s of solve instead of 150 s.",
    ]
    case = Case("seat-room", "Two tiers of the lecture hall's seats in a small room", header,
                patch_size=0.25, hierarchy=(3e-2, 1.0))
    for material, rho in [("floor", 0.25), ("ceiling", 0.75), ("wall", 0.55), ("desk", 0.5), ("wood", 0.35),
                          ("seat", 0.15)]:
        case.material(material, rho)
    front, x0 = 1.5, 0.3
    tiered_shell(case, SEAT_ROOM, 2, front)
    for k in (1, 2):
        seat_block(case, f"row {k}", x0, 4, *tier(k, front), box_seat)
    for i, (x, z) in enumerate([(0.9, 1.3), (2.1, 1.3), (0.9, 3.3), (2.1, 3.3)]):
        case.luminaire(f"downlight {i + 1}", "hall-downlight.ies", (x, h - 0.01, z))
    x = seat_x(x0, 1)[0] + 0.275
    case.probe("row 1, seat 2, pan underside", (x, RISER + 0.399, front + 0.7), (0, -1, 0))
    case.probe("tread 1 under seat 2", (x, RISER, front + 0.7), (0, 1, 0))
    case.probe("row 1, desk", (x, RISER + 0.75, front + 0.2), (0, 1, 0))
    case.probe("ceiling, centre", (w / 2, h, d / 2), (0, -1, 0))
    case.camera("from the back corner", (w - 0.2, 2.6, d - 0.2), (1.2, 0.6, 1.6), 70, (640, 400))
    return case


# ----------------------------------------------------------------------------- the meshed seats


def superellipsoid(centre, half, tilt_deg, n_lon, n_lat, exponent=0.3):
    """A closed rounded box (superellipsoid) as triangles, counter-clockwise seen from
    outside: a latitude-longitude grid of the unit sphere whose coordinates are raised to
    `exponent` (keeping their signs), scaled by `half`, tilted about x (top towards +z),
    moved to `centre`. 2 n_lon (n_lat - 1) triangles."""

    def power(c):
        return math.copysign(abs(c) ** exponent, c)

    t = math.radians(tilt_deg)
    points = []
    for i in range(n_lat + 1):
        theta = math.pi * i / n_lat
        for j in range(n_lon):
            phi = 2 * math.pi * j / n_lon
            s = math.sin(theta)
            x, y, z = (half[0] * power(s * math.cos(phi)), half[1] * power(math.cos(theta)),
                       half[2] * power(s * math.sin(phi)))
            y, z = y * math.cos(t) - z * math.sin(t), y * math.sin(t) + z * math.cos(t)
            points.append((centre[0] + x, centre[1] + y, centre[2] + z))
    at = lambda i, j: i * n_lon + j % n_lon
    triangles = []
    for i in range(n_lat):
        for j in range(n_lon):
            a, b, c, d = at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i + 1, j)
            if i > 0:
                triangles.append((a, b, c))
            if i < n_lat - 1:
                triangles.append((a, c, d))
    return points, triangles  # the poles are rings of coincident points: `Obj` merges them


class Obj:
    """An OBJ file being written: vertices (5 decimals) and triangles, shared points
    of the poles merged so that no triangle has a zero-length edge."""

    def __init__(self):
        self.vertices, self.faces, self.index = [], [], {}

    def add(self, points, triangles):
        ids = []
        for p in points:
            key = tuple(num(c, 5) for c in p)
            if key not in self.index:
                self.index[key] = len(self.vertices) + 1
                self.vertices.append(key)
            ids.append(self.index[key])
        for tri in triangles:
            a, b, c = (ids[v] for v in tri)
            if len({a, b, c}) == 3:
                self.faces.append((a, b, c))

    def text(self, header):
        lines = [f"# {line}" for line in header]
        lines += ["v " + " ".join(v) for v in self.vertices]
        lines += [f"f {a} {b} {c}" for a, b, c in self.faces]
        return "\n".join(lines) + "\n"


def hall_obj(detail):
    """The hall with mesh seats: a cushion and a tilted back cushion per seat, both
    superellipsoids, all 140 seats in one OBJ file."""
    obj = Obj()
    n_lon, n_lat = 32 * detail, 12 * detail

    def mesh_seat(case, name, x0, x1, y, z):
        half_x, cx = (x1 - x0) / 2 - 0.005, (x0 + x1) / 2
        obj.add(*superellipsoid((cx, y + 0.43, z + 0.7), (half_x, 0.04, 0.2), 0, n_lon, n_lat))
        obj.add(*superellipsoid((cx, y + 0.75, z + 0.915), (half_x, 0.25, 0.03), 6, n_lon, n_lat))

    header = HALL_HEADER + [
        "Here every seat is two rounded cushions (superellipsoids) of triangles, all 140 seats",
        "in one OBJ file, hall-obj/seats.obj: not committed (about 8 MB); `make cases` (or the",
        "command below) writes it. Armrests, desks and room as in lecture-hall.toml; roots of",
        "0.5 m (every OBJ triangle is one root: the uniform kernel cannot hold this scene, so",
        "it is solved with the hierarchical kernel, leaves down to 0.25 m)."]
    case = hall_case("lecture hall, meshed seats", "The lecture hall with 140 seats of triangles in one OBJ file",
                     header, mesh_seat, [("seat", 0.15)], patch_size=0.25, hierarchy=(3e-2, 0.5))
    case.mesh("seats", "seat", "hall-obj/seats.obj", len(obj.faces))
    obj_header = [f"The seats of cases/hall-obj.toml: {len(obj.faces):,} triangles, metres, y up.",
                  f"Generated by `{COMMAND}{f' --detail {detail}' if detail != 1 else ''}`."]
    return case, obj.text(obj_header)


# ----------------------------------------------------------------------------- files


def outputs(detail):
    """Every file the script writes: {path relative to cases/: text}, and a summary."""
    office_case, books = office()
    hall = lecture_hall()
    seats = seat_room()
    obj_case, obj_text = hall_obj(detail)
    files = {
        "office.toml": office_case.text(),
        "office-downlight.ies": office_downlight(),
        "lecture-hall.toml": hall.text(),
        "hall-downlight.ies": hall_downlight(),
        "seat-room.toml": seats.text(),
        "hall-obj.toml": obj_case.text(),
        "hall-obj/seats.obj": obj_text,
    }
    summary = [f"office.toml: {office_case.quads:,} quads ({books} books)",
               f"lecture-hall.toml: {hall.quads:,} quads",
               f"seat-room.toml: {seats.quads:,} quads",
               f"hall-obj.toml: {obj_case.quads:,} quads, {obj_case.triangles:,} OBJ triangles"]
    return files, summary, [office_case, hall, seats, obj_case]


def check(directory, files):
    """Compares the committed files with what the script writes; True when all match."""
    stale = []
    for path, text in files.items():
        if path in GENERATED_ONLY:
            continue
        full = os.path.join(directory, path)
        if not os.path.exists(full) or open(full, encoding="utf-8").read() != text:
            stale.append(path)
    for path in stale:
        script = os.path.basename(sys.argv[0])
        print(f"{script}: {os.path.join(directory, path)} differs from what the script writes", file=sys.stderr)
    return not stale


def write(directory, files):
    for path, text in files.items():
        full = os.path.join(directory, path)
        os.makedirs(os.path.dirname(full), exist_ok=True)
        with open(full, "w", encoding="utf-8", newline="\n") as f:
            f.write(text)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--out", default=CASES, help="folder to write into (default: cases/)")
    parser.add_argument("--check", action="store_true", help="compare the committed files, write nothing")
    parser.add_argument("--detail", type=int, default=1, help="OBJ tessellation factor: detail² × the triangles")
    args = parser.parse_args()
    files, summary, cases = outputs(args.detail)
    clashes = [pair for case in cases for pair in overlaps(case)]
    for a, b in clashes:
        print(f"rooms.py: \"{a}\" and \"{b}\" interpenetrate", file=sys.stderr)
    if clashes:
        sys.exit(1)
    if args.check:
        ok = check(args.out, files)
        print("rooms.py: the committed cases are up to date" if ok else "rooms.py: rerun it and commit")
        sys.exit(0 if ok else 1)
    write(args.out, files)
    for line in summary:
        print(f"rooms.py: wrote {line}")


if __name__ == "__main__":
    main()
