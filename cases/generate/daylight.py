#!/usr/bin/env python3
"""Writes the CIE 171:2006 daylight cases (5.9, 5.11, 5.13, 5.14) into cases/cie171/.

    python3 cases/generate/daylight.py           # write every file
    python3 cases/generate/daylight.py --check   # compare the committed files; write nothing

The room is 4 x 4 x 3 m with black (rho = 0) surfaces, so a probe's illuminance is the
sky component plus the externally reflected component of CIE 171 (the ground: rho = 0.3,
uniform luminance below the horizon). The sun is at 60 deg altitude due south and gives
no direct light. CIE's (x, y, z) are ugo's (x, z, y): y is up and CIE's y axis, which
points south, is ugo's z (north = [0, 0, -1]). The sky is the CIE traditional overcast
sky; the tests set `type` to each of the 16 columns of the tables. Standard library only,
deterministic.
"""

import argparse
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(os.path.dirname(HERE), "cie171")


def vec(a):
    return "[" + ", ".join(repr(float(x)) for x in a) + "]"


def rect(name, o, u, v, material="black"):
    return (f'[[surface]]\nname = "{name}"\nshape = "rectangle"\norigin = {vec(o)}\n'
            f'edge_u = {vec(u)}\nedge_v = {vec(v)}\nmaterial = "{material}"\n\n')


def window(name, o, u, v):
    return f'[[window]]\nname = "{name}"\norigin = {vec(o)}\nedge_u = {vec(u)}\nedge_v = {vec(v)}\n\n'


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


def roof(size):
    """5.9: a size x size opening in the middle of the roof."""
    a, b = 2 - size / 2, 2 + size / 2
    comment = f"""
CIE 171:2006, test case 5.9 "Sky component, unglazed roof opening": a black 4 x 4 x 3 m
room with a {size:g} x {size:g} m opening in the middle of its roof. The quantity is the sky
component SC = 100 E / E_h (%), E_h the unobstructed sky's horizontal illuminance: on the
north wall (A-F, 2.75 m down to 0.25 m high, facing south) and on the floor (G-N, 0.25 m
to 3.75 m from the north wall). Tables B.{1 if size == 1 else 3} and B.{2 if size == 1 else 4}.
Written by cases/generate/daylight.py. CIE's (x, y, z) are ugo's (x, z, y); y is up."""
    text = head(comment, f"CIE 171 5.9 roof opening {size:g} x {size:g} m",
                f"Black room, {size:g} x {size:g} m roof opening, CIE overcast sky", 0.0)
    walls = [FLOOR, NORTH, SOUTH, WEST, EAST] + (ceiling_around(a, b) if size < 4 else [])
    text += "".join(rect(*w) for w in walls)
    text += window("roof", (a, 3, a), (b - a, 0, 0), (0, 0, b - a))
    for i, name in enumerate("ABCDEF"):
        text += probe(name, (2, 2.75 - 0.5 * i, 0), (0, 0, 1))
    for i, name in enumerate("GHIJKLMN"):
        text += probe(name, (2, 0, 0.25 + 0.5 * i), (0, 1, 0))
    return text


FILES = {
    "5.9-roof-1x1.toml": lambda: roof(1),
    "5.9-roof-4x4.toml": lambda: roof(4),
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
