#!/usr/bin/env python3
"""Writes the CIE 171:2006 daylight cases (5.9 to 5.14) into cases/cie171/ and the daylit
office, cases/daylit-office.toml.

    python3 cases/generate/daylight.py           # write every file
    python3 cases/generate/daylight.py --check   # compare the committed files; write nothing

The room is 4 x 4 x 3 m with black (rho = 0) surfaces, so a probe's illuminance is the
sky component plus the externally reflected component of CIE 171 (the ground: rho = 0.3,
uniform luminance below the horizon). The sun is at 60 deg altitude due south and gives
no direct light. CIE's (x, y, z) are ugo's (x, z, y): y is up and CIE's y axis, which
points south, is ugo's z (north = [0, 0, -1]). The sky is the CIE traditional overcast
sky; the tests set `type` to each of the 16 columns of the tables. The glazed cases (5.10,
5.12) cover their opening with CIE 171's 6 mm clear glass (glass = "cie171"). Standard
library only, deterministic.
"""

import argparse
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.dirname(HERE)


def vec(a):
    return "[" + ", ".join(repr(float(x)) for x in a) + "]"


def rect(name, o, u, v, material="black"):
    return (f'[[surface]]\nname = "{name}"\nshape = "rectangle"\norigin = {vec(o)}\n'
            f'edge_u = {vec(u)}\nedge_v = {vec(v)}\nmaterial = "{material}"\n\n')


def window(name, o, u, v, glazed=False):
    glass = 'glass = "cie171"\n' if glazed else ""
    return f'[[window]]\nname = "{name}"\norigin = {vec(o)}\nedge_u = {vec(u)}\nedge_v = {vec(v)}\n{glass}\n'


def probe(name, p, n):
    return f'[[probe]]\nname = "{name}"\nposition = {vec(p)}\nnormal = {vec(n)}\n\n'


def head(comment, name, description, ground):
    lines = "".join(f"# {line}\n" if line else "#\n" for line in comment.strip("\n").split("\n"))
    return (lines + f'\n[scene]\nname = "{name}"\ndescription = "{description}"\n\n'
            "[discretization]\npatch_size = 0.5\n\n"
            '[[material]]\nname = "black"\ntype = "lambert"\nreflectance = 0.0\n\n'
            '[sky]\ntype = "overcast"\nsun_altitude_deg = 60.0\nsun_azimuth_deg = 180.0\n'
            f"horizontal_illuminance = 10000.0\nground_reflectance = {ground}\n\n")


# Walls of the 4 x 4 x 3 room seen from inside (normal = edge_u x edge_v).
FLOOR = ("floor", (0, 0, 0), (0, 0, 4), (4, 0, 0))
NORTH = ("north wall", (0, 0, 0), (4, 0, 0), (0, 3, 0))      # z = 0, faces +z (south)
SOUTH = ("south wall", (0, 0, 4), (0, 3, 0), (4, 0, 0))      # z = 4, faces -z
WEST = ("west wall", (0, 0, 0), (0, 3, 0), (0, 0, 4))        # x = 0, faces +x
EAST = ("east wall", (4, 0, 0), (0, 0, 4), (0, 3, 0))        # x = 4, faces -x


def ceiling_around(a, b):
    """The ceiling (y = 3, facing down) with a hole [a, b] x [a, b] in x and z."""
    return [
        ("ceiling west", (0, 3, 0), (a, 0, 0), (0, 0, 4)),
        ("ceiling east", (b, 3, 0), (4 - b, 0, 0), (0, 0, 4)),
        ("ceiling north", (a, 3, 0), (b - a, 0, 0), (0, 0, a)),
        ("ceiling south", (a, 3, b), (b - a, 0, 0), (0, 0, 4 - b)),
    ]


def roof(size, glazed=False):
    """5.9 (5.10 glazed): a size x size opening in the middle of the roof."""
    a, b = 2 - size / 2, 2 + size / 2
    case, title, glass = ("5.10", "Sky component, glazed roof opening",
                          "\nIt is glazed with CIE 171's 6 mm clear glass (its test 5.5).") if glazed \
        else ("5.9", "Sky component, unglazed roof opening", "")
    first = (5 if size == 1 else 7) if glazed else (1 if size == 1 else 3)
    comment = f"""
CIE 171:2006, test case {case} "{title}": a black 4 x 4 x 3 m
room with a {size:g} x {size:g} m opening in the middle of its roof.{glass} The quantity is the sky
component SC = 100 E / E_h (%), E_h the unobstructed sky's horizontal illuminance: on the
north wall (A-F, 2.75 m down to 0.25 m high, facing south) and on the floor (G-N, 0.25 m
to 3.75 m from the north wall). Tables B.{first} and B.{first + 1}.
Written by cases/generate/daylight.py. CIE's (x, y, z) are ugo's (x, z, y); y is up."""
    text = head(comment, f"CIE 171 {case} roof opening {size:g} x {size:g} m" + (", glazed" if glazed else ""),
                f"Black room, {size:g} x {size:g} m {'glazed ' if glazed else ''}roof opening, CIE overcast sky", 0.0)
    walls = [FLOOR, NORTH, SOUTH, WEST, EAST] + (ceiling_around(a, b) if size < 4 else [])
    text += "".join(rect(*w) for w in walls)
    text += window("roof", (a, 3, a), (b - a, 0, 0), (0, 0, b - a), glazed)
    for i, name in enumerate("ABCDEF"):
        text += probe(name, (2, 2.75 - 0.5 * i, 0), (0, 0, 1))
    for i, name in enumerate("GHIJKLMN"):
        text += probe(name, (2, 0, 0.25 + 0.5 * i), (0, 1, 0))
    return text


def south_wall_around(x0, x1, y0, y1):
    """The south wall (z = 4, facing north, -z) with a hole [x0, x1] x [y0, y1]."""
    pieces = [
        ("south wall below", (0, 0, 4), (0, y0, 0), (4, 0, 0)),
        ("south wall above", (0, y1, 4), (0, 3 - y1, 0), (4, 0, 0)),
        ("south wall west", (0, y0, 4), (0, y1 - y0, 0), (x0, 0, 0)),
        ("south wall east", (x1, y0, 4), (0, y1 - y0, 0), (4 - x1, 0, 0)),
    ]
    return [p for p in pieces if p[2][1] > 0 and p[3][0] > 0]


def facade(width, height, sill, case="5.11", mask=""):
    """5.11, 5.13, 5.14: an opening in the south wall; the points of 5.11 (A-F on the
    north wall, G-N on the floor and G'-N' on the ceiling, G and G' farthest from the
    opening) or of 5.13 and 5.14 (A-H on the floor, A farthest)."""
    x0, x1, y0, y1 = 2 - width / 2, 2 + width / 2, sill, sill + height
    tables = {"5.11": "B.9 to B.14", "5.12": "B.15 to B.20", "5.13": "B.21 to B.23", "5.14": "B.24 to B.26"}[case]
    what = {
        "5.11": "the back (north) wall (A-F, 2.75 m down to 0.25 m high), the floor (G-N)\nand the ceiling (G'-N', ERC alone), 0.25 m to 3.75 m from the back wall",
        "5.12": "the back (north) wall (A-F, 2.75 m down to 0.25 m high), the floor (G-N)\nand the ceiling (G'-N', ERC alone), 0.25 m to 3.75 m from the back wall",
        "5.13": "the floor (A-H, 0.25 m to 3.75 m from the back wall), under a black\nhorizontal mask (an overhang at the top of the facade, 4 m wide)",
        "5.14": "the floor (A-H, 0.25 m to 3.75 m from the back wall), facing a black vertical\nmask (a wall 100 m long, parallel to the facade, 6 m in front of it)",
    }[case]
    title = {"5.11": "Sky component plus externally reflected component, unglazed facade opening",
             "5.12": "SC + ERC, glazed facade opening",
             "5.13": "SC + ERC with a horizontal mask", "5.14": "SC + ERC with a vertical mask"}[case]
    comment = f"""
CIE 171:2006, test case {case} "{title}": a black 4 x 4 x 3 m room with a {width:g} x {height:g} m
opening ({sill:g} m sill) in its south wall{mask and ', ' + mask}. The ground outside has rho = 0.3 and
a uniform luminance. The quantity is SC + ERC = 100 E / E_h (%) on
{what}. Tables {tables}.
Written by cases/generate/daylight.py. CIE's (x, y, z) are ugo's (x, z, y); y is up."""
    name = f"CIE 171 {case} facade opening {width:g} x {height:g} m" + (f", {mask}" if mask else "")
    glazed = "glazed " if case == "5.12" else ""
    text = head(comment, name, f"Black room, {width:g} x {height:g} m {glazed}facade opening, CIE overcast sky", 0.3)
    walls = [FLOOR, NORTH, WEST, EAST] + south_wall_around(x0, x1, y0, y1)
    walls += [("ceiling", (0, 3, 0), (4, 0, 0), (0, 0, 4))]
    text += "".join(rect(*w) for w in walls)
    return text, (x0, x1, y0, y1)


def facade_511(width, height, sill, glazed=False):
    """5.11 (5.12 glazed with CIE 171's 6 mm clear glass)."""
    case, mask = ("5.12", "glazed with 6 mm clear glass") if glazed else ("5.11", "")
    text, (x0, x1, y0, y1) = facade(width, height, sill, case, mask)
    text += window("facade", (x0, y0, 4), (x1 - x0, 0, 0), (0, y1 - y0, 0), glazed)
    for i, name in enumerate("ABCDEF"):
        text += probe(name, (2, 2.75 - 0.5 * i, 0), (0, 0, 1))
    for i, name in enumerate("GHIJKLMN"):
        text += probe(name, (2, 0, 0.25 + 0.5 * i), (0, 1, 0))
    for i, name in enumerate("GHIJKLMN"):
        text += probe(name + "'", (2, 3, 0.25 + 0.5 * i), (0, -1, 0))
    return text


def masked(case, mask, surface):
    text, (x0, x1, y0, y1) = facade(2, 1, 1, case, mask)
    text += rect(*surface)
    text += window("facade", (x0, y0, 4), (x1 - x0, 0, 0), (0, y1 - y0, 0))
    for i, name in enumerate("ABCDEFGH"):
        text += probe(name, (2, 0, 0.25 + 0.5 * i), (0, 1, 0))
    return text


def overhang(depth):
    return masked("5.13", f"{depth:g} m horizontal mask", ("mask", (0, 3, 4), (4, 0, 0), (0, 0, depth)))


def facing_wall(height):
    return masked("5.14", f"{height:g} m vertical mask", ("mask", (-48, 0, 10), (0, height, 0), (100, 0, 0)))


def office():
    """A 6 x 4 x 3 m office with a 3 x 1.5 m window (0.9 m sill) in its south wall, under
    the CIE overcast sky: ceiling 0.7, walls 0.5, floor 0.2, ground 0.2; a 0.85 m work
    plane grid of 0.25 m cells and three probes along the room's axis."""
    comment = """
A daylit office: 6 x 4 x 3 m (x by z by y), a 3 x 1.5 m opening with a 0.9 m sill in the
south wall (z = 4), the CIE traditional overcast sky of 10 000 lx, the ground rho = 0.2.
Ceiling 0.7, walls 0.5, floor 0.2. The work plane grid (0.85 m, 0.25 m cells) gives the
daylight factor map and its statistics (docs/daylight.md); the probes, SC, ERC and IRC.
Written by cases/generate/daylight.py. y is up, north is -z."""
    lines = "".join(f"# {line}\n" for line in comment.strip("\n").split("\n"))
    text = (lines + '\n[scene]\nname = "daylit office"\n'
            'description = "6 x 4 x 3 m office, 3 x 1.5 m south window, CIE overcast sky"\n\n'
            "[discretization]\npatch_size = 0.25\n\n")
    for name, rho in [("ceiling", 0.7), ("wall", 0.5), ("floor", 0.2)]:
        text += f'[[material]]\nname = "{name}"\ntype = "lambert"\nreflectance = {rho}\n\n'
    text += ('[sky]\ntype = "overcast"\nsun_altitude_deg = 40.0\nsun_azimuth_deg = 180.0\n'
             "horizontal_illuminance = 10000.0\nground_reflectance = 0.2\n\n")
    x0, x1, y0, y1 = 1.5, 4.5, 0.9, 2.4
    walls = [
        ("floor", (0, 0, 0), (0, 0, 4), (6, 0, 0), "floor"),
        ("ceiling", (0, 3, 0), (6, 0, 0), (0, 0, 4), "ceiling"),
        ("north wall", (0, 0, 0), (6, 0, 0), (0, 3, 0), "wall"),
        ("west wall", (0, 0, 0), (0, 3, 0), (0, 0, 4), "wall"),
        ("east wall", (6, 0, 0), (0, 0, 4), (0, 3, 0), "wall"),
        ("south wall below", (0, 0, 4), (0, y0, 0), (6, 0, 0), "wall"),
        ("south wall above", (0, y1, 4), (0, 3 - y1, 0), (6, 0, 0), "wall"),
        ("south wall west", (0, y0, 4), (0, y1 - y0, 0), (x0, 0, 0), "wall"),
        ("south wall east", (x1, y0, 4), (0, y1 - y0, 0), (6 - x1, 0, 0), "wall"),
    ]
    text += "".join(rect(*w) for w in walls)
    text += window("window", (x0, y0, 4), (x1 - x0, 0, 0), (0, y1 - y0, 0))
    text += ('[[grid]]\nname = "work_plane"\norigin = [0.0, 0.85, 0.0]\nedge_u = [6.0, 0.0, 0.0]\n'
             "edge_v = [0.0, 0.0, 4.0]\nresolution = [24, 16]\nnormal = [0.0, 1.0, 0.0]\n\n")
    for name, z in [("front", 3.0), ("middle", 2.0), ("back", 1.0)]:
        text += probe(name, (3, 0.85, z), (0, 1, 0))
    text += probe("ceiling", (3, 3, 3), (0, -1, 0))
    text += ('[[camera]]\nname = "room"\nposition = [0.4, 1.6, 0.3]\nlook_at = [4.5, 1.2, 4.0]\n'
             "fov_deg = 70.0\nresolution = [480, 360]\n")
    return text


FILES = {
    "daylit-office.toml": office,
    "cie171/5.9-roof-1x1.toml": lambda: roof(1),
    "cie171/5.9-roof-4x4.toml": lambda: roof(4),
    "cie171/5.10-roof-1x1.toml": lambda: roof(1, glazed=True),
    "cie171/5.10-roof-4x4.toml": lambda: roof(4, glazed=True),
    "cie171/5.11-facade-2x1.toml": lambda: facade_511(2, 1, 1),
    "cie171/5.11-facade-4x3.toml": lambda: facade_511(4, 3, 0),
    "cie171/5.12-facade-2x1.toml": lambda: facade_511(2, 1, 1, glazed=True),
    "cie171/5.12-facade-4x3.toml": lambda: facade_511(4, 3, 0, glazed=True),
    "cie171/5.13-overhang-0.5.toml": lambda: overhang(0.5),
    "cie171/5.13-overhang-1.0.toml": lambda: overhang(1.0),
    "cie171/5.13-overhang-2.0.toml": lambda: overhang(2.0),
    "cie171/5.14-facing-wall-3.toml": lambda: facing_wall(3),
    "cie171/5.14-facing-wall-6.toml": lambda: facing_wall(6),
    "cie171/5.14-facing-wall-9.toml": lambda: facing_wall(9),
}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--check", action="store_true", help="compare the committed files; write nothing")
    args = parser.parse_args()
    stale = []
    for name, make in FILES.items():
        path = os.path.join(OUT, name)
        text = make()
        if args.check:
            with open(path, encoding="utf-8") as f:
                if f.read() != text:
                    stale.append(name)
        else:
            with open(path, "w", encoding="utf-8") as f:
                f.write(text)
    if stale:
        sys.exit("stale: " + ", ".join(stale) + " (run python3 cases/generate/daylight.py)")


if __name__ == "__main__":
    main()
