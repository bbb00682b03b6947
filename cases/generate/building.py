#!/usr/bin/env python3
"""Writes ugo's building floor (issue 36, point 4): 28 furnished rooms and a corridor.

    python3 cases/generate/building.py             # write cases/building.toml
    python3 cases/generate/building.py --check     # compare the committed file; write nothing
    python3 cases/generate/building.py --out DIR   # write into DIR instead of cases/

A floor of 60 x 16 x 3 m: a corridor 2 m wide along x (z from 7 to 9) and on each side a
row of rooms 7 m deep: 26 offices (24 of 4 m for one person, 2 of 6 m for two), a meeting
room of 8 m and a stair core (a closed box with a door), joined to the corridor by open
doors (holes in the corridor walls) and lit by recessed downlights (cases/office-downlight.ies)
and by an overcast sky through a glazed window in the facade of every room but the stair
core and at both ends of the corridor. The partitions and corridor walls are two-sided
rectangles of no thickness; the furniture of a row of equal rooms is written once and
copied along the row by `array` (docs/scene-format.md), so the file stays small.

Built on rooms.py: its `Case`, numbers, furniture (`desk`, `office_chair`,
`meeting_chair`, `bookshelf`) and `overlaps` check are imported, not copied. Standard
library only, deterministic (fixed seeds, fixed number formats): running it again rewrites
the committed file byte for byte. Lengths are metres, y is up, north is -z.
"""

import argparse
import os
import random
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from rooms import (BOOKS, CASES, DESK_TOP, Case, Group, bookshelf, check, cross, desk, dot, meeting_chair,  # noqa: E402
                   num, office_chair, overlaps, vec, write)

COMMAND = "python3 cases/generate/building.py"
LENGTH, DEPTH, HEIGHT = 60.0, 16.0, 3.0  # the floor: x, z, y
CORRIDOR = (7.0, 9.0)  # its walls' z
DOOR = (0.9, 2.1)  # a door's width and height
PATCH_SIZE = 0.15  # the leaves: 539,141 when solved (`ugo info` bounds them by 9.45e5)
QUICK_PATCH_SIZE = 1.0  # a quick look

# The rooms, west to east: (label, kind, width). North of the corridor (z from 0 to 7) and
# south of it (z from 9 to 16).
NORTH = [(f"N{i + 1:02}", "office", 4.0) for i in range(7)] + [("N08", "stair", 4.0)] + \
        [(f"N{i + 9:02}", "office", 4.0) for i in range(7)]
SOUTH = [("S01", "office 2", 6.0)] + [(f"S{i + 2:02}", "office", 4.0) for i in range(5)] + \
        [("S07", "meeting", 8.0)] + [(f"S{i + 8:02}", "office", 4.0) for i in range(5)] + [("S13", "office 2", 6.0)]
CORRIDOR_LIGHTS = 15


class Copies:
    """Stands for a `Case` while the first room of a run of `count` equal rooms, `step`
    apart along x, is furnished: each box is written once with `array` copies, prefixed
    by the run's name, and every copy is kept for `overlaps`."""

    def __init__(self, case, prefix, count, step):
        self.case, self.prefix, self.count, self.step = case, prefix, count, step

    def box(self, name, material, lo, hi, rotate=0.0):
        self.case.box(f"{self.prefix}, {name}", material, lo, hi, rotate)
        copy_along(self.case, self.count, self.step, 6)
        for k in range(1, self.count):
            shift = lambda p: (p[0] + k * self.step, p[1], p[2])  # noqa: E731
            self.case.boxes.append((f"{self.prefix}, {name}-{k + 1}", shift(lo), shift(hi), rotate))


def copy_along(case, count, step, quads):
    """Makes the surface just written `count` copies `step` apart along x."""
    if count > 1:
        case.surfaces.insert(len(case.surfaces) - 1, f"array = {{ count = [{count}], step = [[{num(step)}, 0, 0]] }}")
        case.quads += quads * (count - 1)


def rect(case, name, material, origin, u, v, front, holes=(), two_sided=False, count=1, step=0.0):
    """The parallelogram origin + s u + t v, its front towards `front`, with `holes`
    ((at, size) in metres along u and v), copied `count` times `step` apart along x."""
    swapped = dot(cross(u, v), front) < 0
    if swapped:
        u, v, holes = v, u, [(at[::-1], size[::-1]) for at, size in holes]
    rows = ["[[surface]]", f'name = "{name}"', 'shape = "rectangle"', f'material = "{material}"',
            f"origin = {vec(origin)}", f"edge_u = {vec(u)}", f"edge_v = {vec(v)}"]
    if two_sided:
        rows.append("two_sided = true")
    if holes:
        rows.append("holes = [" + ", ".join(f"{{ at = {vec(at)}, size = {vec(size)} }}" for at, size in holes) + "]")
    case.surfaces += rows + [""]
    case.quads += 1
    copy_along(case, count, step, 1)
    return swapped


def window(case, name, wall, at, size, swapped):
    """A window of CIE 171 glass cut into `wall` (a rectangle whose edges `rect` swapped
    when `swapped`), at (at, size) along the wall and up."""
    if swapped:
        at, size = at[::-1], size[::-1]
    case.windows += ["[[window]]", f'name = "{name}"', f'wall = "{wall}"', f"at = {vec(at)}", f"size = {vec(size)}",
                     'glass = "cie171"', ""]


def runs(rooms):
    """The rooms grouped into runs of equal kind and width: (x0, count, first label,
    last label, kind, width)."""
    out, x = [], 0.0
    for label, kind, width in rooms:
        if out and out[-1][4] == kind and out[-1][5] == width:
            x0, count, first, _, _, _ = out[-1]
            out[-1] = (x0, count + 1, first, label, kind, width)
        else:
            out.append((x, 1, label, label, kind, width))
        x += width
    return out


def span(first, last):
    return first if first == last else f"{first}-{last}"


def across(north, z):
    """z on the north side as written, mirrored on the south side (its facade at z = 16)."""
    return z if north else DEPTH - z


def door_at(width):
    """A room's door: 0.3 m from its west partition, or in the middle of a wide room."""
    return 0.3 if width <= 4.0 else width / 2 - DOOR[0] / 2


def shell(case, north, rooms):
    """Per run of rooms: floors, ceilings, the corridor wall with a door per room, the
    partitions east of each room (the last room's east wall is the end wall); per room the
    facade with its window."""
    z_out, z_in = across(north, 0.0), CORRIDOR[0] if north else CORRIDOR[1]
    inward = 1 if north else -1  # from the facade into the room, along z
    for x0, count, first, last, kind, width in runs(rooms):
        name = span(first, last)
        z0, z1 = min(z_out, z_in), max(z_out, z_in)
        rect(case, f"{name} floor", "floor", (x0, 0, z0), (width, 0, 0), (0, 0, z1 - z0), (0, 1, 0),
             count=count, step=width)
        rect(case, f"{name} ceiling", "ceiling", (x0, HEIGHT, z0), (width, 0, 0), (0, 0, z1 - z0), (0, -1, 0),
             count=count, step=width)
        doors = [(door_at(width), 0.0)] if kind != "meeting" else [(1.0, 0.0), (width - 1.0 - DOOR[0], 0.0)]
        rect(case, f"{name} corridor wall", "wall", (x0, 0, z_in), (width, 0, 0), (0, HEIGHT, 0), (0, 0, inward),
             holes=[(at, DOOR) for at in doors], two_sided=True, count=count, step=width)
        partitions = count if x0 + count * width < LENGTH else count - 1
        if partitions:
            rect(case, f"{name} partition", "wall", (x0 + width, 0, z0), (0, 0, z1 - z0), (0, HEIGHT, 0), (1, 0, 0),
                 two_sided=True, count=partitions, step=width)
    x = 0.0
    for label, kind, width in rooms:
        wall = f"{label} facade"
        swapped = rect(case, wall, "wall", (x, 0, z_out), (width, 0, 0), (0, HEIGHT, 0), (0, 0, inward))
        if kind != "stair":
            window(case, f"{label} window", wall, (0.5, 0.9), (width - 1.0, 1.5), swapped)
        x += width


def ends(case):
    """The end walls x = 0 and x = 60, one rectangle per room or corridor, a tall window
    at each end of the corridor."""
    spans = [("north", 0.0, CORRIDOR[0]), ("corridor", CORRIDOR[0], CORRIDOR[1]), ("south", CORRIDOR[1], DEPTH)]
    for end, x, inward in (("west", 0.0, 1), ("east", LENGTH, -1)):
        for part, z0, z1 in spans:
            wall = f"{end} end, {part}"
            swapped = rect(case, wall, "wall", (x, 0, z0), (0, 0, z1 - z0), (0, HEIGHT, 0), (inward, 0, 0))
            if part == "corridor":
                window(case, f"corridor {end} window", wall, (0.3, 0.3), (1.4, 2.4), swapped)


def office_furniture(sink, x0, north, persons, width, rng):
    """A desk with its chair per person facing the facade, a low cabinet under the window,
    a bookshelf against the east partition."""
    turn = 0 if north else 180
    xs = [x0 + width / 2] if persons == 1 else [x0 + 1.6, x0 + width - 1.6]
    for i, x in enumerate(xs):
        label = f"desk {i + 1}" if persons > 1 else "desk"
        desk(sink, label, (x, 0, across(north, 1.7)), turn)
        office_chair(sink, f"chair {i + 1}" if persons > 1 else "chair", (x, 0, across(north, 2.35)), (turn + 180) % 360)
    z0, z1 = sorted((across(north, 0.0), across(north, 0.45)))
    cabinet = Group(sink, "cabinet", (x0 + 0.7, 0, (z0 + z1) / 2))
    cabinet.box("carcass", "cabinet", (-0.4, 0.0, -0.225), (0.4, 0.7, 0.225))
    cabinet.box("top", "wood", (-0.4, 0.7, -0.225), (0.4, 0.72, 0.225))
    z0, z1 = sorted((across(north, 3.4), across(north, 5.4)))
    bookshelf(sink, rng, x0 + width, z0, z1)


def stair(case, x0, north):
    """Twelve steps up along z and a landing, between the partitions of the stair core."""
    rise, tread = 0.17, 0.28
    for i in range(12):
        z0, z1 = sorted((across(north, 1.0 + i * tread), across(north, 1.0 + (i + 1) * tread)))
        case.box(f"stair, step {i + 1}", "floor", (x0 + 0.2, 0, z0), (x0 + 1.9, (i + 1) * rise, z1))
    z0, z1 = sorted((across(north, 1.0 + 12 * tread), across(north, 6.0)))
    case.box("stair, landing", "floor", (x0 + 0.2, 0, z0), (x0 + 3.8, 12 * rise, z1))


def meeting(case, x0, north):
    """A table for eight along x, its chairs, a whiteboard on the west partition."""
    zc = across(north, 3.5)
    table = Group(case, "meeting table", (x0 + 4.0, 0, zc))
    table.box("top", "desk", (-1.8, 0.72, -0.6), (1.8, 0.75, 0.6))
    table.box("leg 1", "metal", (-1.5, 0, -0.4), (-1.46, 0.72, 0.4))
    table.box("leg 2", "metal", (1.46, 0, -0.4), (1.5, 0.72, 0.4))
    seats = [(x, zc - 1.05, 0) for x in (-1.2, 0, 1.2)] + [(x, zc + 1.05, 180) for x in (-1.2, 0, 1.2)]
    seats += [(-2.3, zc, 90), (2.3, zc, -90)]
    for i, (dx, z, angle) in enumerate(seats):
        meeting_chair(case, f"meeting chair {i + 1}", (x0 + 4.0 + dx, 0, z), angle)
    z0, z1 = sorted((across(north, 1.5), across(north, 5.5)))
    case.box("whiteboard", "whiteboard", (x0, 0.9, z0), (x0 + 0.02, 2.1, z1))


def furnish(case, rooms, north, rng):
    for x0, count, first, last, kind, width in runs(rooms):
        if kind.startswith("office"):
            sink = Copies(case, span(first, last), count, width)
            office_furniture(sink, x0, north, 2 if kind == "office 2" else 1, width, rng)
        elif kind == "stair":
            stair(case, x0, north)
        elif kind == "meeting":
            meeting(case, x0, north)


def layout(kind):
    """A room's downlights: (columns along x, rows along z)."""
    return (1, 3) if kind == "office" else (2, 2) if kind == "stair" else (2, 3)


def lights(case, rooms, north):
    """Per room a luminaire array of its own light-scene group (the room's label):
    one column of three downlights in a one-person office, two columns elsewhere."""
    x = 0.0
    for label, kind, width in rooms:
        columns, rows = layout(kind)
        z0, z1 = sorted((across(north, 0.0), across(north, CORRIDOR[0])))
        case.luminaires += [
            "[[luminaire]]", f'name = "{label} downlight"', 'type = "ies"', 'file = "office-downlight.ies"',
            f"array = {{ rows = {rows}, columns = {columns}, origin = {vec((x, HEIGHT - 0.01, z0))}, "
            f"edge_u = {vec((width, 0, 0))}, edge_v = {vec((0, 0, z1 - z0))} }}",
            f'group = "{label}"', ""]
        x += width


def building():
    rng = random.Random(36)
    rooms = NORTH + SOUTH
    offices = sum(kind.startswith("office") for _, kind, _ in rooms)
    case = Case("building", f"A floor of {len(rooms)} furnished rooms, 60 x 16 x 3 m: {offices} offices, a meeting "
                f"room, a stair core, a corridor; {DOWNLIGHTS} downlights and {WINDOWS} windows under an overcast sky",
                HEADER, patch_size=PATCH_SIZE, hierarchy=(1e-2, 1.0), command=COMMAND)
    case.windows = []
    case.lines += ["", "[sky]", 'type = "overcast"', "horizontal_illuminance = 10000", "ground_reflectance = 0.2"]
    for name, rho in [("floor", 0.2), ("ceiling", 0.8), ("wall", 0.6), ("desk", 0.5), ("metal", 0.35),
                      ("monitor", 0.05), ("fabric", 0.12), ("cabinet", 0.7), ("wood", 0.4), ("whiteboard", 0.8)]:
        case.material(name, rho)
    for i, rho in enumerate(BOOKS):
        case.material(f"book {i + 1}", rho)

    case.comment("North rooms (z from 0 to 7): floors, ceilings, corridor walls with their doors, partitions, "
                 "facades (two-sided walls of no thickness but the facades).")
    shell(case, True, NORTH)
    case.comment("South rooms (z from 9 to 16).")
    shell(case, False, SOUTH)
    case.comment("The corridor (z from 7 to 9) and the end walls, a window at each end of the corridor.")
    rect(case, "corridor floor", "floor", (0, 0, CORRIDOR[0]), (LENGTH, 0, 0), (0, 0, 2.0), (0, 1, 0))
    rect(case, "corridor ceiling", "ceiling", (0, HEIGHT, CORRIDOR[0]), (LENGTH, 0, 0), (0, 0, 2.0), (0, -1, 0))
    ends(case)
    case.comment("The facade windows, cut into the facade of their room (CIE 171's 6 mm clear glass).")
    case.surfaces += case.windows
    case.comment("Furniture: each piece of the first office of a run, copied along the run.")
    furnish(case, NORTH, True, rng)
    furnish(case, SOUTH, False, rng)

    lights(case, NORTH, True)
    lights(case, SOUTH, False)
    case.luminaires += [
        "[[luminaire]]", 'name = "corridor downlight"', 'type = "ies"', 'file = "office-downlight.ies"',
        f"array = {{ rows = 1, columns = {CORRIDOR_LIGHTS}, origin = {vec((0, HEIGHT - 0.01, CORRIDOR[0]))}, "
        f"edge_u = {vec((LENGTH, 0, 0))}, edge_v = {vec((0, 0, 2.0))} }}", 'group = "corridor"', ""]

    case.probe("N04 desk, top", (14.0, DESK_TOP, 1.7), (0, 1, 0))
    case.probe("S04 desk, top", (16.0, DESK_TOP, DEPTH - 1.7), (0, 1, 0))
    case.probe("S01 desk 1, top", (1.6, DESK_TOP, DEPTH - 1.7), (0, 1, 0))
    case.probe("corridor floor, x = 14.6", (14.6, 0, 8.0), (0, 1, 0))
    case.probe("corridor floor, middle", (30.0, 0, 8.0), (0, 1, 0))
    case.probe("corridor, facing the N04 door", (12.75, 1.0, 8.0), (0, 0, -1))
    case.probe("meeting table, centre", (30.0, 0.75, DEPTH - 3.5), (0, 1, 0))
    case.probe("stair, landing", (30.0, 12 * 0.17, 5.0), (0, 1, 0))
    case.grid("N04 work plane", (12.5, 0.75, 0.5), (3.0, 0, 0), (0, 0, 6.0), (6, 12), (0, 1, 0))
    case.camera("corridor", (1.0, 1.6, 8.0), (30.0, 1.2, 8.0), 70, (800, 400))
    return case


DOWNLIGHTS = CORRIDOR_LIGHTS + sum(c * r for c, r in (layout(kind) for _, kind, _ in NORTH + SOUTH))
WINDOWS = 2 + sum(kind != "stair" for _, kind, _ in NORTH + SOUTH)  # the corridor's two and the rooms'
HEADER = [
    "A floor of an office building, 60 x 16 x 3 m (issue 36, point 4): a corridor 2 m wide",
    f"along x (z from 7 to 9) between two rows of rooms 7 m deep, {len(NORTH + SOUTH)} rooms. North",
    "(z < 7), west to east: offices N01-N07 (4 m), the stair core N08 (a closed box with a",
    "door, twelve steps and a landing), offices N09-N15. South: S01 (6 m, two persons),",
    "S02-S06 (4 m), the meeting room S07 (8 m, a table for eight, a whiteboard), S08-S12,",
    "S13 (6 m, two persons). Every office: desks with monitors and chairs, a cabinet under",
    "the window, a bookshelf with books. Open doors (0.9 x 2.1 m holes in the corridor",
    "walls; two into the meeting room); a window of CIE 171 glass (sill 0.9 m, 1.5 m high,",
    "0.5 m from the partitions) in the facade of every room but the stair core, and one at",
    f"each end of the corridor ({WINDOWS} windows), under a CIE overcast sky of 10,000 lx.",
    f"{DOWNLIGHTS} recessed downlights (office-downlight.ies, 3,400 lm): three per one-person",
    "office, six in the two-person offices and the meeting room, four in the stair core,",
    f"{CORRIDOR_LIGHTS} in the corridor; each room's downlights are a light-scene group named by its",
    "label, the corridor's \"corridor\" (no [[light_scene]] here: each group would cost a",
    "solve). Hierarchical kernel: roots of 1 m, links to 1e-2, leaves down to "
    f"{num(PATCH_SIZE)} m",
    "(539,141 leaves and 16.3 M links when solved; `ugo info cases/building.toml` bounds the",
    "leaves by 9.45e5). A quick look, leaves of 1 m:",
    f"`ugo solve cases/building.toml --patch-size {num(QUICK_PATCH_SIZE)}`.",
]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--out", default=CASES, help="folder to write into (default: cases/)")
    parser.add_argument("--check", action="store_true", help="compare the committed file, write nothing")
    args = parser.parse_args()
    case = building()
    clashes = overlaps(case)
    for a, b in clashes:
        print(f"building.py: \"{a}\" and \"{b}\" interpenetrate", file=sys.stderr)
    if clashes:
        sys.exit(1)
    files = {"building.toml": case.text()}
    if args.check:
        ok = check(args.out, files)
        print("building.py: the committed case is up to date" if ok else "building.py: rerun it and commit")
        sys.exit(0 if ok else 1)
    write(args.out, files)
    print(f"building.py: wrote building.toml: {case.quads:,} quads, {len(case.boxes):,} boxes")


if __name__ == "__main__":
    main()
